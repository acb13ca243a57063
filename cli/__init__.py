"""The ``guided-lfd`` command-line layer (typer + rich), one module per subcommand."""

import time

#: When this process started loading guided-lfd's command line: the console
#: script's ``--time-limit`` counts from here, so start-up counts too.
PROCESS_STARTED = time.monotonic()

#: Set to :data:`PROCESS_STARTED` by the console script (:func:`cli.main.run`);
#: None when the commands run in-process (tests): their clock starts per call.
run_started: float | None = None
