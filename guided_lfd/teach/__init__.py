"""Guided teaching, the paper's whole loop: excuse -> request -> demonstration -> learn -> merge -> re-plan.

Each round asks for the demonstration the robot needs (its minimal excuse,
in the paper's words: ``Open PinkDrawer``), says why it needs it and what to
leave as it is, takes the demonstration (a hand trace; or, simulated, the
human model's shortest plan to the request rendered as one), segments it,
learns its skills, merges them into the robot's domain and re-plans from
the state the demonstration left.  Rounds go on until the robot can plan
the task, no demonstration is given, or the rounds run out.

The session ends ``solved`` only when the taught robot plans the original
task from its original state: a demonstration that reached the goal while
the skills learned from it do not let the robot plan the task ends
``demonstration-only``.  When no excuse exists because no skill of the robot
makes some goal atom true, the round asks for a demonstration of a new skill
that does (its request is those atoms).

The package, one job per module: :mod:`~guided_lfd.teach.session` (the
session's model and its documents), :mod:`~guided_lfd.teach.request` (what a
round asks for and why, in words), :mod:`~guided_lfd.teach.human` (the
demonstrators: the simulated human, recorded traces), :mod:`~guided_lfd.teach.learning`
(a round's demonstration learned and merged), :mod:`~guided_lfd.teach.check` (each demonstration checked
against its request: accepted, partial, misdirected, unhelpful or inconsistent), :mod:`~guided_lfd.teach.folder`
(the session folder), :mod:`~guided_lfd.teach.skill_request` (a round that asks for a skill once more, from a
skill excuse, and the teacher's "cannot"), :mod:`~guided_lfd.teach.loop` (the rounds) and
:mod:`~guided_lfd.teach.library` (a sequence of tasks, each from the skill library the earlier ones left).
"""

from __future__ import annotations

from guided_lfd.teach.check import OUTCOMES, DemonstrationCheck
from guided_lfd.teach.human import GivenTraces, SimulatedHuman, check_human_model
from guided_lfd.teach.library import TeachLibrary, teach_tasks
from guided_lfd.teach.loop import teach
from guided_lfd.teach.request import keep_facts
from guided_lfd.teach.session import Demonstrator, Round, TeachSession

__all__ = ["Round", "TeachSession", "SimulatedHuman", "GivenTraces", "teach", "keep_facts", "check_human_model",
           "Demonstrator", "DemonstrationCheck", "OUTCOMES", "TeachLibrary", "teach_tasks"]
