"""The ``guided-lfd`` command-line layer (typer + rich), one module per subcommand."""

import time

#: When this process started loading guided-lfd's command line: the console
#: script's ``--time-limit`` counts from here, so start-up counts too.
PROCESS_STARTED = time.monotonic()
