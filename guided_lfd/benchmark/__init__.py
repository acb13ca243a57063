"""The excuse benchmark: tasks made unsolvable by removing a skill, and their runs.

A benchmark task is an IPC (or kitchen) task whose robot domain lacks one
action schema, kept if the robot can no longer solve it.  The excuse space
fixes the predicates no action of the *complete* domain changes (roads, floor
order, type predicates): what no agent in that world can change
(``--fixed-from`` the complete domain).  Every strategy and semantics runs
on every task in its own process with the same time limit; rows go to a CSV
and a markdown summary with plots is written from it.

One stage per module, data flowing one way:
:mod:`~guided_lfd.benchmark.suite` (the tasks) ->
:mod:`~guided_lfd.benchmark.runner` (whole command-line runs) ->
:mod:`~guided_lfd.benchmark.results` (rows and their CSV) ->
:mod:`~guided_lfd.benchmark.analysis` (comparisons with the baseline) ->
:mod:`~guided_lfd.benchmark.report` (markdown and plots).
:mod:`~guided_lfd.benchmark.household` generates the household series'
tasks (``benchmarks/household/scaling.py``, ``benchmarks/teach_bench.py``).
"""

from guided_lfd.benchmark.analysis import (
    FIRST_TASKS, NONTRIVIAL_S, SEARCH_TIME_FLOOR, SIZE_BUCKETS, Comparison, compare, search_speedup, size_bucket,
    speedups_by_size, suite_part, whole_run_s,
)
from guided_lfd.benchmark.report import limit_section, plot, summary_markdown
from guided_lfd.benchmark.results import (
    GAVE_UP, RESULT_FIELDS, SOLVED, ResultRow, RowLog, merge_rows, read_results, write_results,
)
from guided_lfd.benchmark.runner import (
    KILL_GRACE_S, STOP_AFTER_UNFINISHED, Run, chains, cli_command, command_line, crashed, not_run, run_chain,
    run_one, run_suite,
)
from guided_lfd.benchmark.suite import (
    SUITE_FIELDS, BenchTask, check_removed_actions, generate_suite, input_digest, read_suite, robot_domain_file,
    task_digest, write_suite,
)

__all__ = [
    "FIRST_TASKS", "NONTRIVIAL_S", "SEARCH_TIME_FLOOR", "SIZE_BUCKETS", "Comparison", "compare", "search_speedup",
    "size_bucket", "speedups_by_size", "suite_part", "whole_run_s", "limit_section", "plot", "summary_markdown",
    "GAVE_UP", "RESULT_FIELDS", "SOLVED", "RowLog", "merge_rows", "read_results", "write_results", "KILL_GRACE_S",
    "STOP_AFTER_UNFINISHED", "Run", "chains", "cli_command", "command_line", "crashed", "not_run", "run_chain",
    "run_one", "run_suite", "SUITE_FIELDS", "BenchTask", "generate_suite", "read_suite", "check_removed_actions",
    "robot_domain_file", "write_suite", "ResultRow", "input_digest", "task_digest",
]
