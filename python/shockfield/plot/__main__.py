"""``python -m shockfield.plot KIND RUN [--out PNG]`` (kinds: shockfield.plot.KINDS)."""

import argparse
import sys

from ..errors import InputError
from . import KINDS, plot

parser = argparse.ArgumentParser(prog="python -m shockfield.plot", description=__doc__,
                                 epilog="; ".join(f"{k}: {what}" for k, (_, what) in KINDS.items()))
parser.add_argument("kind")
parser.add_argument("run")
parser.add_argument("--out")
parser.add_argument("--columns", help="thermo, series: comma-separated columns to draw")
args = parser.parse_args()
try:
    print("wrote", plot(args.kind, args.run, args.out, args.columns.split(",") if args.columns else None))
except InputError as error:
    print(f"error: {error}", file=sys.stderr)
    sys.exit(2)
