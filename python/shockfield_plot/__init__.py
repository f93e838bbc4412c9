"""Plotting helpers for shockfield's CSV output (matplotlib; run with Debian's /usr/bin/python3)."""
