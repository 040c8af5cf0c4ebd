"""The deviations of awlsim from the reference that `spec/` documents: the one list.

``check`` names the requirements that determined the *reference's* output at the first
differing row, and the earlier row: the latest row that wrote that output (the start, the set,
R), with the rules that determined it there (and those that acted on the state there, when the
differing row wrote the output too). Each entry says which documented requirement awlsim departs from, where `spec/`
documents awlsim's behaviour (a file and words that must occur on one line of it with the
requirement's ID and "awlsim"; the runner verifies this against the tree), and when a
difference is this deviation: a predicate on the first differing row (its column, ``check``'s
rules at the row and at the earlier row, the inputs, awlsim's and the reference's outputs).
Where ``check`` names the requirement, the predicate asks for the name; it adds a condition on
the rows where the name alone would also accept a different departure, and tests the rows alone
where ``check`` does not name the requirement (the reference follows it without it acting: the
phase of the ticks, LC's word, PT <= 0, a clock gap). A difference that no entry accepts fails
the run.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import reference


@dataclass(frozen=True)
class Case:
    """The first differing row of a trace, as the predicates see it."""

    block: str
    rows: list  # the trace's rows up to and including the differing one (inputs, preset)
    got: list  # awlsim's outputs for those rows
    want: list  # the reference's outputs
    column: str  # the first differing column (check's)
    rules: tuple  # the requirement IDs check names as deciding it at the row
    earlier: tuple = ()  # those it names at the earlier row where they acted and still matter
    earlier_index: int | None = None  # that earlier row's index in ``rows``, or None

    @property
    def named(self) -> frozenset:
        """Every requirement check names: at the row and at the earlier row."""
        return frozenset(self.rules) | frozenset(self.earlier)

    @property
    def row(self) -> dict:
        return self.rows[-1]

    def bit(self, i: int, col: str) -> bool:
        return str(self.rows[i].get(col, 0)).strip().lower() in ("1", "true")


@dataclass(frozen=True)
class Deviation:
    rule: str  # the requirement awlsim departs from
    spec: str  # the file of spec/ that documents it
    words: tuple  # words on the documenting line, besides the ID and "awlsim"
    awlsim: str  # what awlsim does, in a line
    applies: Callable[[Case], bool]
    tag: str = ""  # tells two entries of one requirement apart

    @property
    def name(self) -> str:
        return f"{self.rule} ({self.tag})" if self.tag else self.rule


S5_TIMERS = ("S_PULSE", "S_PEXT", "S_ODT", "S_ODTS", "S_OFFDT")
S5_COUNTERS = ("S_CU", "S_CD", "S_CUD")


def _tick_phase(c: Case) -> bool:
    """BI one unit apart (awlsim: remaining time from the deadline, rounded; reference: whole
    ticks of the base), or Q at an expiry that check attributes to the ticks."""
    if c.block not in S5_TIMERS:
        return False
    if c.column == "BI":
        return abs(c.got[-1]["BI"] - c.want[-1]["BI"]) == 1
    return c.column == "Q" and "S5TMR-TICK-01" in c.rules


def _bcd_value(word: int) -> int:
    return (word >> 8 & 0xF) * 100 + (word >> 4 & 0xF) * 10 + (word & 0xF)


def _lc_word(c: Case) -> bool:
    """BI and Q agree but LC's word does not, in one of the two forms measured: only the base
    bits differ and the digits are 000 (awlsim keeps the base bits after R), or the base is
    1 s or 10 s and LC's digits are one unit below L's value (awlsim's LC rounds down there)."""
    if c.block not in S5_TIMERS or c.column != "BCD":
        return False
    g, w = c.got[-1], c.want[-1]
    if g["BI"] != w["BI"] or g["Q"] != w["Q"]:
        return False
    gb, wb = g["BCD"], w["BCD"]
    base_kept = gb & 0x0FFF == wb & 0x0FFF == 0 and gb != wb
    rounded_down = (gb & 0x3000 == wb & 0x3000 and gb >> 12 & 3 >= 2
                    and g["BI"] - _bcd_value(gb) == 1)
    return base_kept or rounded_down


def _lc_half_unit(c: Case) -> bool:
    """On the 10 ms or 100 ms base, awlsim's own L and LC one unit apart while L agrees with
    the reference: at an exact half unit, L's round(remaining / base) and LC's
    round(remaining * 100) (or * 10) fall on different sides."""
    if c.block not in S5_TIMERS or c.column != "BCD":
        return False
    g, w = c.got[-1], c.want[-1]
    return (g["BI"] == w["BI"] and g["Q"] == w["Q"] and g["BCD"] >> 12 & 3 < 2
            and abs(_bcd_value(g["BCD"]) - g["BI"]) == 1)


def _zero(c: Case) -> bool:
    """Q differs where check names S5TMR-ZERO-01 (a timer started with value 0)."""
    return c.block in S5_TIMERS and c.column == "Q" and "S5TMR-ZERO-01" in c.named


def _odts_restart(c: Case) -> bool:
    """S_ODTS restarted (S edge or FR) after its time ran out: the reference keeps Q = 1."""
    return (c.block == "S_ODTS" and c.column == "Q" and "SS-Q-01" in c.rules
            and c.want[-1]["Q"] and not c.got[-1]["Q"])


def _odt_restart(c: Case) -> bool:
    return (c.block == "S_ODT" and c.column == "Q" and "SD-Q-01" in c.rules
            and c.got[-1]["Q"] and not c.want[-1]["Q"])


def _set_with_count_held(c: Case) -> bool:
    """check names the set (SC-SET-01), and a set (rising S, or S with a rising FR) found CU or
    CD at 1, that input held since. The name alone is not enough: check also names the set when
    a count input that rose again after it is miscounted."""
    if c.block not in S5_COUNTERS or "SC-SET-01" not in c.named:
        return False
    n = len(c.rows)
    for j in range(n - 1):
        rising_s = c.bit(j, "S") and (j == 0 or not c.bit(j - 1, "S"))
        rising_fr = c.bit(j, "S") and c.bit(j, "FR") and (j == 0 or not c.bit(j - 1, "FR"))
        if not (rising_s or rising_fr):
            continue
        for x in ("CU", "CD"):
            if all(c.bit(k, x) for k in range(j, n)):
                return True
    return False


def _pt_not_positive(c: Case) -> bool:
    """PT <= 0 in this row or the one before (awlsim's SFB resets on PT = 0)."""
    return c.block in ("TP", "TON", "TOF") and any(
        reference.time_ms(c.rows[i]["PT"]) <= 0 for i in (-1, -2) if len(c.rows) >= -i)


def _pt_changed(c: Case) -> bool:
    """check names IEC-PT-LATCH-01 and PT changed since the earlier row (where the time
    started and PT was latched), or within the trace when there is none. The name alone is not
    enough: every start latches PT, so check names it at any start (TP's retrigger too). PT <= 0
    at the row is IEC-PT0-01's: awlsim's reset explains it whatever PT was latched."""
    if c.block not in ("TP", "TON", "TOF") or "IEC-PT-LATCH-01" not in c.named:
        return False
    pts = {reference.time_ms(r["PT"]) for r in c.rows[c.earlier_index or 0:]}
    return len(pts) > 1 and reference.time_ms(c.row["PT"]) > 0


def _clock_wrap(c: Case) -> bool:
    """2^31 ms or more between the earlier row (the start) and the differing row: awlsim's
    31-bit clock aliases the gap. check names IEC-WRAP-01 only where the reference's own
    32-bit clock wraps or the CPU time has passed 2^32 ms, not for a gap of 2^31 ms before
    that, so the gap is the test."""
    j = c.earlier_index
    return (c.block in ("TP", "TON", "TOF") and j is not None
            and int(c.row["t_ms"]) - int(c.rows[j]["t_ms"]) >= 2**31)


def _named(rule: str) -> Callable[[Case], bool]:
    return lambda c: rule in c.named


DOCUMENTED = [
    Deviation("S5TMR-TICK-01", "spec/s5.md", ("deadline",),
              "computes the remaining time from a deadline in ms and rounds it: BI steps at the "
              "phase of the start, not on the whole multiples of the base", _tick_phase),
    Deviation("S5TMR-LOAD-01", "spec/s5.md", ("LC",),
              "gives with LC a word that L's value does not: the base bits kept after R, "
              "the digits rounded down on the 1 s and 10 s bases", _lc_word),
    Deviation("S5TMR-LOAD-01", "spec/s5.md", ("half unit",),
              "computes L and LC of the same timer with two floating-point expressions that "
              "round differently at an exact half unit of the 10 ms and 100 ms bases (BI 11, "
              "LC W#16#0012)", _lc_half_unit, tag="half unit"),
    Deviation("S5TMR-ZERO-01", "spec/s5.md", ("first access",),
              "lets a timer started with value 0 run out at its first access, even the same "
              "box's read of Q", _zero),
    Deviation("SD-Q-01", "spec/s5.md", ("FR",),
              "keeps Q = 1 through an FR restart of an expired S_ODT", _odt_restart),
    Deviation("SS-Q-01", "spec/s5.md", ("restarted",),
              "loses Q = 1 when an S_ODTS is restarted after its time ran out, when no access "
              "saw the expiry before the restart", _odts_restart),
    Deviation("SC-SET-01", "spec/counter.md", ("clear",),
              "does not clear the count memories on a set: a count input held through the "
              "set does not count", _set_with_count_held),
    Deviation("TP-RETRIGGER-01", "spec/matrix.md", (),
              "drops a rising IN in the call where the pulse runs out",
              _named("TP-RETRIGGER-01")),
    Deviation("IEC-PT-LATCH-01", "spec/iec.md", ("live",),
              "reads PT live on every call", _pt_changed),
    Deviation("IEC-PT0-01", "spec/iec.md", ("reset",),
              "treats PT = 0 as a reset in SFB 3, 4, 5 (and a negative PT as an error: "
              "Q = 0, ET = 0)", _pt_not_positive),
    Deviation("IEC-WRAP-01", "spec/iec.md", ("31 bits",),
              "uses a 31-bit millisecond clock: gaps alias at 2^31 ms", _clock_wrap),
]


def classify(case: Case):
    """The documented deviation that explains this first difference, or None."""
    for d in DOCUMENTED:
        if d.applies(case):
            return d
    return None


def spec_line(repo, d: Deviation):
    """The line of ``d.spec`` that names the requirement, awlsim and the entry's words, or
    None."""
    try:
        text = (repo / d.spec).read_text(encoding="utf-8")
    except OSError:
        return None
    for ln in text.splitlines():
        if d.rule in ln and "awlsim" in ln.lower() and all(w in ln for w in d.words):
            return ln
    return None


def spec_row(repo, d: Deviation) -> str:
    """The first cell of the documenting table row (the open point it decides), or the
    paragraph's line that names it."""
    ln = spec_line(repo, d) or ""
    cells = [c.strip() for c in ln.split("|")]
    return cells[1] if len(cells) > 2 else ln.strip()


def verify(repo) -> list:
    """The entries whose spec file has no line naming the requirement, awlsim and the words."""
    bad = []
    for d in DOCUMENTED:
        try:
            text = (repo / d.spec).read_text(encoding="utf-8")
        except OSError as e:
            bad.append(f"{d.rule}: {d.spec}: {e}")
            continue
        if not any(d.rule in ln and "awlsim" in ln.lower() and all(w in ln for w in d.words)
                   for ln in text.splitlines()):
            words = "".join(f", `{w}`" for w in d.words)
            bad.append(f"{d.rule}: no line of {d.spec} names {d.rule}, awlsim{words}")
    return bad
