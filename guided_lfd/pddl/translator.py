"""Fast Downward's translator as guided-lfd hands it tasks: the model written as PDDL and parsed back.

The translator (normalisation, grounding, invariant synthesis) works on its
own task objects, which it builds from PDDL text.  Every round trip goes
through this module, so that the text is written by the project's one writer,
the translator's options are set once, and its progress reports (on stdout,
which carries this tool's data) are swallowed.
"""

from __future__ import annotations

import contextlib
import io
from dataclasses import replace
from typing import Any, Iterator

from guided_lfd.pddl.model import Domain, Problem
from guided_lfd.pddl.writer import domain_to_pddl, problem_to_pddl

__all__ = ["translator_options", "quiet", "parse_text", "translator_task", "find_invariants"]


def translator_options() -> Any:
    """The translator's options, set once (its parser and grounder refuse to run without them)."""
    from fast_downward.translate import options

    if options.options is None:
        options.set_options(["domain.pddl", "problem.pddl"])
    return options.options


@contextlib.contextmanager
def quiet(sink: io.StringIO | None = None) -> Iterator[io.StringIO]:
    """The translator's reports on stdout and stderr kept in ``sink`` (a new one if not given), not printed."""
    sink = sink if sink is not None else io.StringIO()
    with contextlib.redirect_stdout(sink), contextlib.redirect_stderr(sink):
        yield sink


def parse_text(domain_text: str, problem_text: str) -> Any:
    """The translator's task read from a domain's and a problem's PDDL text."""
    from fast_downward.translate.pddl_parser import lisp_parser, parsing_functions

    translator_options()
    return parsing_functions.parse_task(lisp_parser.parse_nested_list(domain_text.splitlines(keepends=True)),
                                        lisp_parser.parse_nested_list(problem_text.splitlines(keepends=True)))


def translator_task(domain: Domain, problem: Problem) -> Any:
    """The translator's task for a domain and problem of the model (the problem named for the domain)."""
    return parse_text(domain_to_pddl(domain), problem_to_pddl(replace(problem, domain_name=domain.name)))


def find_invariants(task: Any, max_time: int) -> list:
    """Fast Downward's lifted invariants of the translator's ``task`` (normalised here), within ``max_time``
    seconds of its synthesis."""
    from fast_downward.translate import invariant_finder, normalize

    translator_options().invariant_generation_max_time = max_time
    normalize.normalize(task)
    return list(invariant_finder.find_invariants(task, None))
