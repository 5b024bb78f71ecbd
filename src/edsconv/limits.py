"""How far edsconv reads input, and how it shows a user's text in a message.

The limits an input is refused past live here, so that every command inherits them
(docs/architecture.md, "Refusing input"): the size of an EDS file, the digits of a
number, and the width of a value echoed in a message.
"""

from __future__ import annotations

#: The largest EDS file read, in bytes. The largest real file is 364 KB and generated
#: ones reach tens of MB; past this the syntax model alone would take gigabytes.
MAX_EDS_BYTES = 64 * 1024 * 1024

#: The significant decimal digits read of one number. ULINT's maximum has 20 and an
#: instance number 10; past 40 a number is outside every range, so its value is never
#: computed (Python refuses more than 4,300 digits, against quadratic conversion).
MAX_DIGITS = 40

#: What :func:`decimal` gives for a number of more than MAX_DIGITS digits: larger than
#: every range, and cheap to print.
TOO_MANY_DIGITS = 10 ** MAX_DIGITS

#: The longest value a message echoes whole; longer ones are cut (diff cuts at the same width).
SHOWN_WIDTH = 60


def decimal(digits: str) -> int:
    """The value of a run of decimal digits: the one place where the digits of an input become an int.

    Past MAX_DIGITS significant digits the value is :data:`TOO_MANY_DIGITS`, which every
    range check refuses (EDS102) instead of Python raising on the conversion.
    """
    significant = digits.lstrip("0")
    if len(significant) > MAX_DIGITS:
        return TOO_MANY_DIGITS
    return int(significant or "0")


def cut(text: str, width: int = SHOWN_WIDTH) -> str:
    """``text`` whole when short, else its start, '...' and how long it was."""
    if len(text) <= width:
        return text
    return f"{text[:width - 3]}... ({len(text)} characters)"


def shown(text: str) -> str:
    """A user's text as a message quotes it: as written (``'\\q'`` is shown ``'\\q'``, not a Python
    repr with doubled backslashes), control characters escaped, long values cut."""
    visible = "".join(character if character.isprintable() else repr(character)[1:-1] for character in text)
    return f"'{cut(visible)}'"
