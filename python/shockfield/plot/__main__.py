"""``python -m shockfield.plot KIND RUN [--out PNG] [options]``; ``shockfield plot`` runs this with
its own arguments (SHOCKFIELD_PROG names it in the help). Exit code 2 for bad input (an unknown
kind, a run the kind does not draw: the message lists the kinds the run has)."""

import argparse
import os
import sys

from ..errors import InputError
from . import KINDS, plot


def parser():
    width = max(len(k) for k in KINDS)
    kinds = "\n".join(f"  {name:<{width}}  {kind.what}" for name, kind in KINDS.items())
    p = argparse.ArgumentParser(
        prog=os.environ.get("SHOCKFIELD_PROG", "python -m shockfield.plot"),
        description="Draw a PNG figure of a run folder (default RUN/KIND.png).",
        epilog=f"kinds:\n{kinds}", formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("kind", help="what to draw (the list below)")
    p.add_argument("run", help="run folder (hugoniot, structures: that output folder; slice: an annotated dump)")
    p.add_argument("-o", "--out", help="PNG file (default RUN/KIND.png)")
    p.add_argument("--columns", help="thermo, series: comma-separated columns to draw")
    p.add_argument("--axis", choices=["x", "y", "z"],
                   help="md profiles: the shock axis (default the run's profile_axis); slice: its normal (z)")
    p.add_argument("--at", type=float, help="slice: its centre along --axis (Å; default the middle of the box)")
    p.add_argument("--thickness", type=float, default=3.0, help="slice: its thickness (Å; default 3)")
    p.add_argument("--column", help="slice: the structure column (default acna, else cna, else bpa)")
    p.add_argument("--frame", type=int, default=-1, help="slice: the frame of the dump, 0 the first, -1 the last")
    p.add_argument("--compare", help="hugoniot: a peer sweep CSV (up_km_s, us_km_s, us_stderr_km_s)")
    return p


def main(argv=None):
    a = parser().parse_args(argv)
    try:
        out = plot(a.kind, a.run, a.out, a.columns.split(",") if a.columns else None, axis=a.axis, at=a.at,
                   thickness=a.thickness, column=a.column, frame=a.frame, compare=a.compare)
    except InputError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    print("wrote", out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
