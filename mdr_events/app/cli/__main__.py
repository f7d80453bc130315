"""``python -m mdr_events.app.cli``: the console script ``mdr-events``."""

import sys

from mdr_events.app.cli import console_main

if __name__ == "__main__":  # pragma: no cover
    sys.exit(console_main())
