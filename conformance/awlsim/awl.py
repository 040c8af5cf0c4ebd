"""awlsim's CPU, in this process, running one block's STL program one OB1 cycle per trace row.

The CPU (``awlsim.core.main.AwlSim`` around ``awlsim.core.cpu.S7CPU``) reads the time only in
``S7CPU.updateTimestamp``, which sets ``cpu.now`` (float seconds) from a clock function plus an
offset that ``initializeTimestamp`` (called by ``reset``) chooses so that its 31-bit millisecond
TIME wraps 100 ms after start. Timers read ``cpu.now``: the S5 timers (``core/timers.py``) keep a
deadline ``now + TV`` and compute the remaining time from it; the SFBs read ``cpu.now_TIME``
(``int(now * 1000) & 0x7FFFFFFF``). The runner replaces ``updateTimestamp`` on the CPU instance
by the same method bound to a ``VirtualClock`` and sets the offset to 0, so ``now`` is the row's
``t_ms``: the timers then run on trace time, and nothing in awlsim is changed.
"""

from __future__ import annotations

import functools

from awlsim.common.sources import AwlSource
from awlsim.common.cpuconfig import S7CPUConfig
from awlsim.core.main import AwlSim
from awlsim.core.cpu import S7CPU
from awlsim.awlcompiler.tokenizer import AwlParser

import program
import reference

_TREES: dict = {}


def _tree(block: str):
    if block not in _TREES:
        p = AwlParser()
        p.parseSource(AwlSource(name=block, sourceBytes=program.stl(block).encode()))
        _TREES[block] = p.getParseTree()
    return _TREES[block]


def _preset_word(kind: str, value) -> int:
    if kind == "s5time":
        return reference.s5time_word(value)
    if kind == "time":
        return reference.time_ms(value) & 0xFFFFFFFF
    if kind == "int":
        return int(value) & 0xFFFF
    return program.counter_preset_word(value)


class Cpu:
    """A fresh awlsim CPU loaded with ``block``'s program, on a virtual clock at 0."""

    def __init__(self, block: str) -> None:
        self.block = block
        self.layout = program.layout(block)
        self.clock = program.VirtualClock()
        self.sim = sim = AwlSim()
        sim.reset()
        cpu = self.cpu = sim.getCPU()
        cpu.getConf().setConfiguredMnemonics(S7CPUConfig.MNEMONICS_EN)
        cpu.updateTimestamp = functools.partial(S7CPU.updateTimestamp, cpu, _getTime=self.clock)
        cpu._S7CPU__nowOffset = 0.0  # initializeTimestamp's offset: now is the clock itself
        cpu.updateTimestamp()
        sim.load(_tree(block))
        sim.build()
        sim.startup()

    def cycle(self, row: dict, preset) -> dict:
        """Set the inputs of ``row``, run one OB1 cycle at ``row['t_ms']``, read the outputs."""
        lay = self.layout
        if "t_ms" in row:
            self.clock.set(int(row["t_ms"]))
        else:  # counters without time: a row per millisecond
            self.clock.set(self.clock.t_ms + 1)
        ib = self.cpu.inputs.getRawDataBytes()
        byte = 0
        for col, bit in lay.bits.items():
            if _truth(row.get(col, 0)):
                byte |= 1 << bit
        ib[0] = byte
        name, offset, width, kind = lay.preset
        value = row.get(name, preset)
        if value is None:
            raise ValueError(f"{self.block} needs its preset {name}: a column or an option")
        ib[offset:offset + width] = _preset_word(kind, value).to_bytes(width, "big")
        self.sim.runCycle()
        qb = self.cpu.outputs.getRawDataBytes()
        out = {}
        for col, (kind, where) in lay.outputs.items():
            if kind == "bit":
                out[col] = bool(qb[0] >> where & 1)
            elif kind == "word":
                out[col] = int.from_bytes(qb[where:where + 2], "big")
            elif kind == "int":
                out[col] = int.from_bytes(qb[where:where + 2], "big", signed=True)
            else:
                out[col] = int.from_bytes(qb[where:where + 4], "big", signed=True)
        return out


def _truth(v) -> bool:
    if isinstance(v, str):
        return v.strip().lower() in ("1", "true")
    return bool(v)


def run(block: str, rows: list, preset=None) -> list:
    """awlsim's outputs for each row of the trace, from a fresh CPU."""
    cpu = Cpu(block)
    return [cpu.cycle(row, preset) for row in rows]
