"""Quoted values (docs_current.py's fifth check): a number the docs quote from an example's run is
followed by a marker naming where the example prints it,

    P = 48.96 GPa<!-- value: md_shock_piston pressure_GPa -->

    <!-- value: EXAMPLE LABEL[#K] [±TOL[%]] -->

EXAMPLE is a folder of examples/ with a run.sh; LABEL a word of what run.sh prints (a key such as
`pressure_GPa`, `p*`) or a "quoted phrase" (`"ps: a"`); the value is the K-th number (default 1)
after LABEL on the last line of that output that names LABEL (as a word: not inside another name;
a number is one standing alone, not the 44 of C44). The quoted number is the last
number before the marker on its line (`−` read as a minus). They agree when the printed value
rounds to the quoted digits (48.96 quotes 48.955 … 48.965; 47.2 does not quote 47.96), or, with
±TOL, when they differ by at most TOL (±0.5% relative): for a run that is not bit-reproducible
(MD on several threads is chaotic, so its last digits move between runs), the marker says so.
Markdown hides the comment, so the page reads as before.
"""
import re

MARKER = re.compile(r'<!--\s*value:\s*(\S+)\s+("[^"]+"|[^\s"#]+)(?:#(\d+))?(?:\s+±([0-9.eE+-]+)(%?))?\s*-->')
# A number standing alone: not the digits of a name (C44, time_ps) nor the tail of another number.
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def markers(text):
    """(line number, quoted number text or None, example, label, k, tolerance, relative) per marker."""
    for number, line in enumerate(text.splitlines(), 1):
        for m in MARKER.finditer(line):
            before = NUMBER.findall(line[: m.start()].replace("−", "-"))
            yield (number, before[-1] if before else None, m.group(1), m.group(2).strip('"'), int(m.group(3) or 1),
                   float(m.group(4)) if m.group(4) else None, m.group(5) == "%")


def printed_value(output, label, k):
    """The k-th number after `label` on the last line of `output` naming it, or None."""
    word = re.compile(rf"(?<![\w*]){re.escape(label)}(?![\w*])")
    lines = [line for line in output.splitlines() if word.search(line)]
    if not lines:
        return None
    # a range printed as lo..hi is two numbers
    after = NUMBER.findall(lines[-1][word.search(lines[-1]).end():].replace("..", " "))
    return float(after[k - 1]) if len(after) >= k else None


def half_unit(quoted):
    """Half a unit in the last digit the quoted text gives: 48.96 -> 0.005, 5e-3 -> 0.5e-3, 608 -> 0.5."""
    mantissa, _, exponent = quoted.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def agrees(quoted, value, tolerance, relative):
    q = float(quoted)
    if tolerance is not None:
        return abs(q - value) <= (tolerance / 100 * abs(value) if relative else tolerance)
    return abs(q - value) <= half_unit(quoted) * (1 + 1e-9)


def stale_values(path, text, root, printed):
    """Problems of the markers of one file. `printed` maps an example to its run.sh output, for the
    examples a test ran; markers of the others are checked for their form only."""
    for number, quoted, example, label, k, tolerance, relative in markers(text):
        where = f"{path}:{number}: value of {example} `{label}`"
        if not (root / "examples" / example / "run.sh").exists():
            yield f"{where}: examples/{example}/run.sh does not exist"
        elif quoted is None:
            yield f"{where}: no number before the marker"
        elif example in printed:
            value = printed_value(printed[example], label, k)
            if value is None:
                yield f"{where}: its run.sh printed no number {k} after `{label}`"
            elif not agrees(quoted, value, tolerance, relative):
                allowed = f"±{tolerance:g}{'%' if relative else ''}" if tolerance is not None else "to the digits quoted"
                yield f"{where}: quoted {quoted}, the run printed {value:g} (agreement {allowed})"


def unchecked_examples(files_text, printed):
    """Examples with printed output but no marker anywhere: nothing of theirs is checked."""
    named = {example for text in files_text for _, _, example, *_ in markers(text)}
    return sorted(set(printed) - named)
