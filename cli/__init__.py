"""The ``guided-lfd`` command-line layer (typer + rich), one module per subcommand."""

import os
import signal
import sys
import time


def _stopped_while_starting(signum: int, frame: object) -> None:
    """Ctrl-C or SIGTERM before the command line is loaded: one line and the documented code, at once (a
    KeyboardInterrupt inside ``import typer`` was a traceback; SIGTERM there was 130)."""
    terminated = signum == signal.SIGTERM
    try:
        os.write(2, b"terminated (SIGTERM)\n" if terminated else b"interrupted\n")
    except OSError:
        pass
    os._exit(143 if terminated else 130)


if os.path.basename(sys.argv[0]) == "guided-lfd":  # the console script, not a program importing the package
    signal.signal(signal.SIGINT, _stopped_while_starting)
    signal.signal(signal.SIGTERM, _stopped_while_starting)

#: When this process started loading guided-lfd's command line: the console
#: script's ``--time-limit`` counts from here, so start-up counts too.
PROCESS_STARTED = time.monotonic()

#: Whether a command has said it was interrupted (cli.common.command); the console script says it otherwise.
interruption_reported = False

#: Set to :data:`PROCESS_STARTED` by the console script (:func:`cli.main.run`);
#: None when the commands run in-process (tests): their clock starts per call.
run_started: float | None = None
