"""guided-lfd: excuse-guided learning from demonstration.

The library behind the ``guided-lfd`` command: parse PDDL, ground it, plan and
validate, find minimal excuses (what the robot needs a human to demonstrate),
and learn, merge and evaluate demonstrated skills.
"""

__version__ = "0.1.0"
