"""STL programs for awlsim, one per block, and the map of trace columns to process-image bits.

Each program is one OB1 that executes the block once, the way the STEP 7 box compiles to STL:
the S5 timers as ``FR``, the start operation (``SP SE SD SS SF`` with TV loaded), ``R``, then
``L``, ``LC`` and ``A`` for BI, BCD and Q; the S5 counters as ``FR``, ``CU``, ``CD``, ``S``
(PV loaded), ``R``, then ``L``, ``LC`` and ``A``; the IEC blocks as ``CALL SFB n, DB 10+n`` with
their parameters. Inputs come from the process-image inputs (bits of IB 0, the preset in IW 2
or ID 4), outputs go to the process-image outputs (Q 0.x, QW 2, QW 4, QD 8), which the runner
writes and reads between cycles. This module does not import awlsim.
"""

from __future__ import annotations

from dataclasses import dataclass

#: The STL start operation of each S5 timer (international mnemonics, spec/cli.md aliases).
S5_TIMER_OPS = {"S_PULSE": "SP", "S_PEXT": "SE", "S_ODT": "SD", "S_ODTS": "SS", "S_OFFDT": "SF"}
#: awlsim's system function blocks for the IEC blocks (S7-300/400: SFB 0..5; no TONR).
IEC_SFBS = {"CTU": 0, "CTD": 1, "CTUD": 2, "TP": 3, "TON": 4, "TOF": 5}
S5_COUNTERS = ("S_CU", "S_CD", "S_CUD")


@dataclass(frozen=True)
class Layout:
    """Where a block's trace columns live in the process image.

    ``bits``: trace input column -> bit of IB 0; ``preset``: (column, byte offset, width in
    bytes, kind) with kind ``"s5time"``, ``"time"``, ``"int"`` or ``"bcd"``; ``outputs``: output
    column -> (``"bit"``, bit of QB 0) or (``"word"``/``"dword"``/``"int"``, byte offset).
    """

    block: str
    bits: dict
    preset: tuple
    outputs: dict


def layout(block: str) -> Layout:
    """The process-image layout of ``block`` (a name from the catalog, upper case)."""
    if block in S5_TIMER_OPS:
        return Layout(block, {"S": 0, "R": 1, "FR": 2}, ("TV", 2, 2, "s5time"),
                      {"Q": ("bit", 0), "BI": ("word", 2), "BCD": ("word", 4)})
    if block in ("TP", "TON", "TOF"):
        return Layout(block, {"IN": 0}, ("PT", 4, 4, "time"),
                      {"Q": ("bit", 0), "ET": ("dword", 8)})
    if block == "CTU":
        return Layout(block, {"CU": 0, "R": 2}, ("PV", 2, 2, "int"),
                      {"Q": ("bit", 0), "CV": ("int", 2)})
    if block == "CTD":
        return Layout(block, {"CD": 1, "LD": 3}, ("PV", 2, 2, "int"),
                      {"Q": ("bit", 0), "CV": ("int", 2)})
    if block == "CTUD":
        return Layout(block, {"CU": 0, "CD": 1, "R": 2, "LD": 3}, ("PV", 2, 2, "int"),
                      {"QU": ("bit", 0), "QD": ("bit", 1), "CV": ("int", 2)})
    if block in S5_COUNTERS:
        bits = {"CU": 0, "CD": 1, "S": 2, "R": 3, "FR": 4}
        if block == "S_CU":
            del bits["CD"]
        if block == "S_CD":
            del bits["CU"]
        return Layout(block, bits, ("PV", 2, 2, "bcd"),
                      {"Q": ("bit", 0), "CV": ("word", 2), "CV_BCD": ("word", 4)})
    raise ValueError(f"awlsim has no counterpart of {block!r}; it runs "
                     f"{', '.join([*S5_TIMER_OPS, *IEC_SFBS, *S5_COUNTERS])}")


def _lines(*insns: str) -> str:
    return "".join(f"\t{i}\n" for i in insns)


def stl(block: str) -> str:
    """The STL source (OB1, and the instance DB of an SFB) executing ``block`` once per cycle."""
    lay = layout(block)
    b = lay.bits
    if block in S5_TIMER_OPS:
        body = _lines(f"A I 0.{b['FR']}", "FR T 1",
                      f"A I 0.{b['S']}", "L IW 2", f"{S5_TIMER_OPS[block]} T 1",
                      f"A I 0.{b['R']}", "R T 1",
                      "L T 1", "T QW 2", "LC T 1", "T QW 4",
                      "A T 1", "= Q 0.0")
        return f"ORGANIZATION_BLOCK OB 1\nBEGIN\n{body}END_ORGANIZATION_BLOCK\n"
    if block in S5_COUNTERS:
        insns = [f"A I 0.{b['FR']}", "FR C 1"]
        if "CU" in b:
            insns += [f"A I 0.{b['CU']}", "CU C 1"]
        if "CD" in b:
            insns += [f"A I 0.{b['CD']}", "CD C 1"]
        insns += [f"A I 0.{b['S']}", "L IW 2", "S C 1",
                  f"A I 0.{b['R']}", "R C 1",
                  "L C 1", "T QW 2", "LC C 1", "T QW 4",
                  "A C 1", "= Q 0.0"]
        body = _lines(*insns)
        return f"ORGANIZATION_BLOCK OB 1\nBEGIN\n{body}END_ORGANIZATION_BLOCK\n"
    n = IEC_SFBS[block]
    # The trace calls the load input LD; awlsim's SFB 1 and SFB 2 call it LOAD.
    params = [f"{'LOAD' if col == 'LD' else col} := I 0.{bit}" for col, bit in b.items()]
    params.append(f"PV := IW {lay.preset[1]}" if lay.preset[0] == "PV"
                  else f"PT := ID {lay.preset[1]}")
    for col, (kind, where) in lay.outputs.items():
        params.append({"bit": f"{col} := Q 0.{where}", "word": f"{col} := QW {where}",
                       "int": f"{col} := QW {where}", "dword": f"{col} := QD {where}"}[kind])
    db = 10 + n  # DB 0 does not exist
    call = f"CALL SFB {n}, DB {db} (\n" + ",\n".join(f"\t\t{p}" for p in params) + "\n\t)"
    return (f"ORGANIZATION_BLOCK OB 1\nBEGIN\n\t{call}\nEND_ORGANIZATION_BLOCK\n"
            f"DATA_BLOCK DB {db}\n\tSFB {n}\nBEGIN\nEND_DATA_BLOCK\n")


def bcd3(n: int) -> int:
    """``n`` (0..999) as three BCD digits, the form ``S C n`` loads (C#n)."""
    if not 0 <= n <= 999:
        raise ValueError(f"counter preset {n} out of range 0..999")
    return (n // 100) << 8 | (n // 10 % 10) << 4 | n % 10


def counter_preset_word(text: str) -> int:
    """The word ``S C n`` loads for an S5 counter preset written ``C#n``, ``n`` or ``W#16#0xyz``
    (the forms of spec/cli.md); the word form is passed as written, so awlsim judges it."""
    t = str(text).strip().upper()
    if t.startswith("W#16#"):
        return int(t[5:], 16)
    if t.startswith("C#"):
        t = t[2:]
    return bcd3(int(t))


class VirtualClock:
    """The CPU clock awlsim reads, set by the runner to each row's ``t_ms``.

    awlsim keeps ``now`` as float seconds and converts it to its millisecond TIME with
    ``int(now * 1000.0)``, which truncates. ``t_ms / 1000`` is not exact in binary, so for about
    one ``t_ms`` in a hundred the conversion would give ``t_ms - 1``: an artefact of the virtual
    clock, not of awlsim. The clock therefore reads a quarter millisecond past ``t_ms``; the
    conversion then gives ``t_ms`` exactly, and differences of two readings (the S5 timers'
    deadlines) are unchanged.
    """

    OFFSET_MS = 0.25

    def __init__(self) -> None:
        self.t_ms = 0

    def set(self, t_ms: int) -> None:
        """Move the clock to ``t_ms``; it never goes back (the trace format forbids it)."""
        if t_ms < self.t_ms:
            raise ValueError(f"t_ms {t_ms} is before {self.t_ms}: the clock never goes back")
        self.t_ms = t_ms

    def __call__(self) -> float:
        return (self.t_ms + self.OFFSET_MS) / 1000.0
