"""The rules of issue 20 (EDS224-EDS239, EDS350-EDS369), each with its documentation: where a figure of
the text conflicts with a formula, what the classification says against what the file describes, names
and keyword values no one defines, enumerations beyond their parameter's range.

The checks are in :mod:`edsconv.checks.coherence` (and, for EDS350, in :mod:`edsconv.checks.entities`
beside EDS319); docs/rules.md is generated from these definitions (``edsconv rules --format markdown``).
"""

from __future__ import annotations

from edsconv.diagnostics import Severity, block, rule

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

SCALING_ALL_ZERO = rule(
    "EDS350", WARNING, "C.4.1.4.6", "A parameter supports scaling with every scaling field 0, as Figure C.11 does",
    clause_note="Figures C.5, C.11",
    explanation="""
        The descriptor sets bit 2 (supports scaling) and the multiplier, divisor, base
        and offset are all 0. Figure C.5's formula divides by the divisor, so no
        engineering value exists; but Figure C.11, the text's own example of a chassis
        EDS, writes exactly this (`0x0004` and `0,0,0,0`). Where a figure of the text
        conflicts with its formula the file is not an error: a warning that names both.
        A divisor of 0 beside any other scaling value is no figure's and stays EDS319.
        A ProxiedParam entry alone is not judged by this rule: its fields count only where
        the adapter's Proxy entry says `Module` and are documentation elsewhere (C.4.1.5.3);
        `edsconv merge` checks the entry the pair forms.
    """,
    bad=block("""
        Param1 = 0,,,0x0004,0xC6,1,"Slot Naming Convention","","",0,4,0,0,0,0,0;
    """),
    good=block("""
        Param1 = 0,,,0x0000,0xC6,1,"Slot Naming Convention","","",0,4,0,0,0,0,0;   $ bit 2 clear
    """),
)
