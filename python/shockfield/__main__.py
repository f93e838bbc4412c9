"""``python -m shockfield sweep ...``: the package's commands (``shockfield sweep`` runs this)."""

import sys

from . import sweep

COMMANDS = {"sweep": sweep.main}

if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1] not in COMMANDS:
        print(f"usage: python -m shockfield {{{','.join(COMMANDS)}}} ...", file=sys.stderr)
        sys.exit(2)
    sys.exit(COMMANDS[sys.argv[1]](sys.argv[2:]))
