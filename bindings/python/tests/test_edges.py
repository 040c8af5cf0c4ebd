"""The edges where a foreign value meets the package (issue 37): numpy bool arrays whose bytes
are not 0 or 1, numpy missing, presets of the wrong literal type, the output objects, copies and
pickles, threads, negative sizes and indices, the names the module exports."""

from __future__ import annotations

import copy
import gc
import pickle
import random
import subprocess
import sys
import threading
import time
from typing import Any, Callable, Dict, List, Tuple

import numpy as np
import pytest

import plc_timers
from plc_timers import CounterPreset, S5Time, Time

# --- numpy bool arrays read as bytes ------------------------------------------------------------

EVERY_BYTE = np.arange(256, dtype=np.uint8)


def test_ton_bank_reads_every_byte_as_numpy_does() -> None:
    """A numpy bool array holds bytes; numpy takes any non-zero byte as True. The bank must too:
    every byte 0-255 as IN gives the outputs of TON called with `bool(byte)` (the block, one
    timer at a time, given Python bools)."""
    in_ = EVERY_BYTE.view(np.bool_)
    pt = np.full(256, 100, np.int32)
    bank = plc_timers.TonBank(256)
    timers = [plc_timers.TON(pt=100) for _ in range(256)]
    for now in (0, 60, 100, 130):
        q, et = bank.scan(now, in_, pt)
        want = [t.call(now, in_=bool(b)) for t, b in zip(timers, EVERY_BYTE.tolist())]
        assert q.tolist() == [o.q for o in want], f"IEC-BANK-01: Q at {now} ms"
        assert et.tolist() == [o.et for o in want], f"IEC-BANK-01: ET at {now} ms"
    # numpy's own reading of the array is the oracle of what IN is: 255 lanes on, lane 0 off.
    assert in_.tolist() == [b != 0 for b in range(256)]
    assert q.tolist() == [b != 0 for b in range(256)], "IEC-BANK-01: every non-zero byte is IN"


def test_issue_example_bytes_1_2_255() -> None:
    bank = plc_timers.TonBank(3)
    in_ = np.array([1, 2, 255], np.uint8).view(np.bool_)
    pt = np.full(3, 100, np.int32)
    bank.scan(0, in_, pt)
    q, et = bank.scan(100, in_, pt)
    assert q.tolist() == [True, True, True], "IEC-BANK-01: Q of IN bytes 1, 2, 255"
    assert et.tolist() == [100, 100, 100], "IEC-BANK-01: ET of IN bytes 1, 2, 255"
    # The same bytes as a uint8 array (a process image) are read the same way.
    q8, et8 = plc_timers.TonBank(3).scan(0, np.array([1, 2, 255], np.uint8), np.zeros(3, np.int32))
    assert q8.tolist() == [True, True, True], "IEC-BANK-01: uint8 IN, PT 0"


@pytest.mark.parametrize("port", ["cu", "cd", "r", "ld"])
def test_counter_bank_reads_every_byte_of_every_input(port: str) -> None:
    """Each input of the counter bank as every byte 0-255: the outputs of CTUD called with
    `bool(byte)` on that input (the block, one counter at a time)."""
    pv = 5
    bank = plc_timers.CounterBank(256)
    counters = [plc_timers.CTUD(pv=pv) for _ in range(256)]
    on = EVERY_BYTE.view(np.bool_)
    off = np.zeros(256, np.bool_)
    for k in range(7):
        # The input pulses (on, off, on, …); CU also pulses on the even scans so that R, CD and
        # LD have a count to act on.
        arrays: Dict[str, Any] = {port: on if k % 2 == 0 else off}
        if port != "cu":
            arrays["cu"] = on if k % 4 == 1 else off
        qu, qd, cv = bank.scan(pv=pv, **arrays)
        # The oracle reads the bytes: non-zero is True.
        bytes_of = {name: a.view(np.uint8).tolist() for name, a in arrays.items()}
        want = [
            c.call(pv=pv, **{name: b[i] != 0 for name, b in bytes_of.items()})
            for i, c in enumerate(counters)
        ]
        assert cv.tolist() == [o.cv for o in want], f"CNT-EQUIV-01: CV, {port} bytes, scan {k}"
        assert qu.tolist() == [o.qu for o in want], f"CNT-EQUIV-01: QU, {port} bytes, scan {k}"
        assert qd.tolist() == [o.qd for o in want], f"CNT-EQUIV-01: QD, {port} bytes, scan {k}"


def test_counter_bank_issue_example_counts_once_per_rising_byte() -> None:
    bank = plc_timers.CounterBank(3)
    pulse = np.array([1, 2, 255], np.uint8).view(np.bool_)
    for _ in range(3):
        bank.scan(pv=5, cu=pulse)
        _, _, cv = bank.scan(pv=5)
    assert cv.tolist() == [3, 3, 3], "CNT-EQUIV-01: three rising CU of bytes 1, 2, 255"


def test_bool_outputs_are_written_as_0_or_1_whatever_they_held() -> None:
    """An `out=` array of bool may hold any bytes (np.empty); the bank writes 0 or 1."""
    n = 8
    q = np.full(n, 7, np.uint8).view(np.bool_)
    et = np.zeros(n, np.int32)
    in_ = np.array([1, 0] * 4, np.uint8).view(np.bool_)
    plc_timers.TonBank(n).scan(0, in_, np.zeros(n, np.int32), out=(q, et))
    assert q.view(np.uint8).tolist() == [1, 0] * 4, "IEC-BANK-01: Q bytes are 0 or 1"
    qu = np.full(n, 9, np.uint8).view(np.bool_)
    qd = np.full(n, 9, np.uint8).view(np.bool_)
    cv = np.zeros(n, np.int16)
    plc_timers.CounterBank(n).scan(pv=1, cu=in_, out=(qu, qd, cv))
    assert qu.view(np.uint8).tolist() == [1, 0] * 4, "CNT-EQUIV-01: QU bytes are 0 or 1"
    assert qd.view(np.uint8).tolist() == [0, 1] * 4, "CNT-EQUIV-01: QD bytes are 0 or 1"


# --- without numpy ------------------------------------------------------------------------------

NO_NUMPY = """
import sys

class NoNumpy:
    # A meta-path finder that refuses numpy, as an environment without it does.
    def find_spec(self, name, path=None, target=None):
        if name == "numpy" or name.startswith("numpy."):
            raise ModuleNotFoundError(f"No module named {name!r}")
        return None

sys.meta_path.insert(0, NoNumpy())
import plc_timers

# The blocks need no numpy.
assert plc_timers.TON(pt=500).call(0, in_=True) == plc_timers.IecOutput(q=False, et=0)
for make in (lambda: plc_timers.CounterBank(4), lambda: plc_timers.TonBank(4)):
    try:
        make()
    except Exception as e:  # an Exception, not a panic (a BaseException)
        assert isinstance(e, ImportError), repr(e)
        assert "pip install plc-timers[numpy]" in str(e), str(e)
    else:
        raise AssertionError("a bank was made without numpy")
print("ImportError naming the extra")
"""


def test_banks_without_numpy_raise_import_error_naming_the_extra() -> None:
    done = subprocess.run(
        [sys.executable, "-c", NO_NUMPY], capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    assert "ImportError naming the extra" in done.stdout
    assert "PanicException" not in done.stderr


# --- presets of run and check: one rule with the block classes ----------------------------------

WRONG_TYPE: List[Tuple[str, str, Any, List[str]]] = [
    ("TON", "pt", CounterPreset(5), ["t_ms", "IN"]),
    ("TON", "pt", S5Time.parse("S5T#1S"), ["t_ms", "IN"]),
    ("S_CU", "pv", Time.parse("T#500ms"), ["CU"]),
    ("S_CU", "pv", S5Time.parse("S5T#1S"), ["CU"]),
    ("S_ODT", "tv", Time.parse("T#1S"), ["t_ms", "S"]),
    ("S_ODT", "tv", CounterPreset(5), ["t_ms", "S"]),
    ("CTU", "pv", CounterPreset(5), ["CU"]),
    ("CTU", "pv", Time.parse("T#5MS"), ["CU"]),
    ("TON", "pt", True, ["t_ms", "IN"]),
]


@pytest.mark.parametrize(("block", "keyword", "value", "columns"), WRONG_TYPE)
def test_run_and_check_refuse_a_preset_the_block_refuses(
    block: str, keyword: str, value: Any, columns: List[str]
) -> None:
    """`run`, `check` and the block class read a preset by one rule: a value of another literal
    type is a TypeError in each, with the same message."""
    with pytest.raises(TypeError) as by_class:
        getattr(plc_timers, block)(**{keyword: value})
    rows = [dict.fromkeys(columns, 0)]
    with pytest.raises(TypeError) as by_run:
        plc_timers.run(block, rows, **{keyword: value})
    with pytest.raises(TypeError) as by_check:
        plc_timers.check(block, rows, outputs=[], **{keyword: value})
    assert str(by_run.value) == str(by_class.value) == str(by_check.value)
    assert "--" not in str(by_run.value)


@pytest.mark.parametrize(
    ("block", "keyword", "value", "columns"),
    [
        ("TON", "pt", 2**31, ["t_ms", "IN"]),
        ("S_ODT", "tv", 70000, ["t_ms", "S"]),
        ("S_CU", "pv", 1000, ["CU"]),
        ("CTU", "pv", 40000, ["CU"]),
    ],
)
def test_run_and_check_refuse_a_preset_out_of_range_as_the_block_does(
    block: str, keyword: str, value: int, columns: List[str]
) -> None:
    """An int outside the preset's range: the block class's ValueError, and in `run` and
    `check` the TraceError (a ValueError) of the keyword argument with the same message."""
    presets: Dict[str, Any] = {keyword: value}
    with pytest.raises(ValueError) as by_class:
        getattr(plc_timers, block)(**presets)
    for fn in (plc_timers.run, plc_timers.check):
        with pytest.raises(plc_timers.TraceError) as e:
            fn(block, [dict.fromkeys(columns, 0)], **presets)
        assert e.value.option == keyword
        assert e.value.message == str(by_class.value)
        assert str(e.value) == f"keyword argument {keyword}: {by_class.value}"


def test_an_int_preset_cell_is_read_as_the_keyword_is() -> None:
    """An int TV is a word, PT milliseconds, PV a count, in a cell as in the keyword argument and
    the block class."""
    rows = [(0, 1), (400, 1), (500, 1)]
    cells = [(t, s, 0x2050) for t, s in rows]
    by_cell = plc_timers.run("S_ODT", cells, columns=["t_ms", "S", "TV"])
    by_keyword = plc_timers.run("S_ODT", rows, columns=["t_ms", "S"], tv=0x2050)
    timer = plc_timers.S_ODT(tv=0x2050)
    by_class = [timer.call(t, s=bool(s)) for t, s in rows]
    assert by_cell == by_keyword
    assert [(r["Q"], r["BI"], r["BCD"]) for r in by_cell] == [(o.q, o.bi, o.bcd) for o in by_class]
    # W#16#2050: base 100 ms (bits 13-12 = 2), BCD 050: 5 s; 50 units left at the start.
    assert by_cell[0]["BI"] == 50
    pt_cell = plc_timers.run("TON", [(t, i, 500) for t, i in rows], columns=["t_ms", "IN", "PT"])
    assert pt_cell == plc_timers.run("TON", rows, columns=["t_ms", "IN"], pt=500)
    assert [r["Q"] for r in pt_cell] == [False, False, True]  # PT 500 ms expires at 500
    pv_cell = plc_timers.run("S_CU", [(1, 1, CounterPreset(7))], columns=["CU", "S", "PV"])
    assert pv_cell == plc_timers.run("S_CU", [(1, 1)], columns=["CU", "S"], pv=CounterPreset(7))


def test_a_preset_cell_of_another_type_says_what_is_allowed() -> None:
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.run("S_ODT", [(0, 1, Time.parse("T#1S"))], columns=["t_ms", "S", "TV"])
    assert (e.value.line, e.value.column, e.value.column_name) == (2, 3, "TV")
    assert "a word (int 0..=65535) or an S5Time" in e.value.message
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.run("S_ODT", [(0, 1, 70000)], columns=["t_ms", "S", "TV"])
    assert "0..=65535" in e.value.message


@pytest.mark.parametrize(
    ("block", "kwargs", "says"),
    [
        ("TON", {}, "the keyword argument pt"),
        ("TON", {"tv": "S5T#1S"}, "its preset PT is the keyword argument pt"),
        ("TON", {"pt": "T#1.5S"}, "keyword argument pt: `T#1.5S`"),
        ("TON", {"pt": 1, "type": "DINT"}, "keyword argument type: TON does not take the data type DINT"),
    ],
)
def test_errors_name_keyword_arguments_not_command_line_flags(
    block: str, kwargs: Dict[str, Any], says: str
) -> None:
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.run(block, [{"t_ms": 0, "IN": 1}], **kwargs)
    assert "--" not in str(e.value) and "--" not in e.value.message
    assert says in str(e.value)


# --- output objects -----------------------------------------------------------------------------


def test_outputs_are_constructible_and_compare_with_literals() -> None:
    ton = plc_timers.TON(pt="T#500ms")
    ton.call(1000, in_=True)
    out = ton.call(1500, in_=True)
    # TON with PT 500 ms, IN 1 since 1000 ms: Q = 1, ET = PT at 1500 ms.
    assert out == plc_timers.IecOutput(q=True, et=500)
    assert out != plc_timers.IecOutput(q=True, et=499)
    odt = plc_timers.S_ODT(tv="S5T#50MS").call(0, s=True)
    assert odt == plc_timers.S5Output(q=False, bi=5, bcd=0x0005)
    assert plc_timers.CTU(pv=1).call(cu=True) == plc_timers.CounterOutput(qu=True, qd=False, cv=1)
    assert plc_timers.S_CD(pv="C#1").call(s=True) == plc_timers.S5CounterOutput(
        q=True, cv=1, cv_bcd=0x0001
    )
    for o in (out, odt):
        assert eval(repr(o), vars(plc_timers)) == o
        assert pickle.loads(pickle.dumps(o)) == o
        assert copy.copy(o) == o and hash(copy.deepcopy(o)) == hash(o)
    with pytest.raises(TypeError):
        plc_timers.IecOutput(q=1, et=5)  # type: ignore[arg-type]


# --- copies and pickles -------------------------------------------------------------------------

Step = Callable[[Any, random.Random, int], Any]


def s5_timer_step(b: Any, rng: random.Random, t: int) -> Any:
    return b.call(t, s=rng.random() < 0.6, r=rng.random() < 0.1, fr=rng.random() < 0.2)


def iec_timer_step(b: Any, rng: random.Random, t: int) -> Any:
    reset = rng.random() < 0.1 and isinstance(b, plc_timers.TONR)
    return b.call(t, in_=rng.random() < 0.6, r=reset)


def counter_step(inputs: Tuple[str, ...]) -> Step:
    def step(b: Any, rng: random.Random, t: int) -> Any:
        return b.call(**{i: rng.random() < (0.1 if i in ("r", "s") else 0.5) for i in inputs})

    return step


BLOCKS: List[Tuple[str, Dict[str, Any], Step]] = [
    *[
        (b, {"tv": "S5T#300MS"}, s5_timer_step)
        for b in ("S_PULSE", "S_PEXT", "S_ODT", "S_ODTS", "S_OFFDT")
    ],
    *[(b, {"pt": "T#300ms"}, iec_timer_step) for b in ("TP", "TON", "TOF", "TONR")],
    ("CTU", {"pv": 3, "type": "SINT"}, counter_step(("cu", "r"))),
    ("CTD", {"pv": 3, "type": "UDINT"}, counter_step(("cd", "ld"))),
    ("CTUD", {"pv": 3}, counter_step(("cu", "cd", "r", "ld"))),
    ("S_CU", {"pv": "C#3"}, counter_step(("cu", "s", "r", "fr"))),
    ("S_CD", {"pv": "C#3"}, counter_step(("cd", "s", "r", "fr"))),
    ("S_CUD", {"pv": "C#3"}, counter_step(("cu", "cd", "s", "r", "fr"))),
]


def snapshots(obj: Any) -> List[Any]:
    return [copy.copy(obj), copy.deepcopy(obj), pickle.loads(pickle.dumps(obj))]


@pytest.mark.parametrize("optimized", [False, True])
@pytest.mark.parametrize(("block", "kwargs", "step"), BLOCKS, ids=[b[0] for b in BLOCKS])
def test_blocks_copy_and_pickle_continue_as_the_original(
    block: str, kwargs: Dict[str, Any], step: Step, optimized: bool
) -> None:
    """A copy or an unpickled block, taken half-way, goes on exactly as the original does from
    there (its state, preset, implementation and clock), and is independent of it."""
    original = getattr(plc_timers, block)(optimized=optimized, **kwargs)
    rng = random.Random(f"{block}{optimized}")
    times = sorted(rng.randrange(0, 3000) for _ in range(80))
    for t in times[:40]:
        step(original, rng, t)
    copies = snapshots(original)
    assert all(repr(c) == repr(original) for c in copies)
    seed = rng.random()
    tail = times[40:]
    want = [step(original, r, t) for r in [random.Random(seed)] for t in tail]
    for c in copies:
        assert c.optimized is optimized
        got = [step(c, r, t) for r in [random.Random(seed)] for t in tail]
        assert got == want, f"{block}: a copy differs from the original"


def test_a_pickled_state_no_block_can_be_in_is_refused() -> None:
    ton = plc_timers.TON(pt=500)
    state = ton.__reduce__()[2]
    optimized, pt, last, fields = state
    bad = (optimized, pt, last, (fields[0], fields[1], fields[2], fields[3], 5, 10, fields[6]))
    with pytest.raises(ValueError, match="not a state of TON"):
        ton.__setstate__(bad)  # ET 10 > PT 5
    with pytest.raises(ValueError, match="not a state of S_CU"):
        plc_timers.S_CU().__setstate__((False, None, None, (1000, False, False, False, False)))


def test_memory_areas_copy_and_pickle() -> None:
    area = plc_timers.TimerMemory(64)
    area.advance_to(0)
    area.start(3, "SD", True, "S5T#200MS")
    area.advance_to(150)
    copies = snapshots(area)
    area.advance_to(200)
    for c in copies:
        assert (c.now_ms, c.load(3), c.status(3)) == (150, 5, False)
        c.advance_to(200)
        assert (c.load(3), c.status(3)) == (area.load(3), area.status(3)) == (0, True)
        with pytest.raises(ValueError, match="goes backwards"):
            c.advance_to(199)
    counters = plc_timers.CounterMemory(64)
    counters.set(5, True, "C#2")
    counters.cd(5, True)
    for c in snapshots(counters):
        assert c.load(5) == 1
        c.cd(5, False)
        c.cd(5, True)
        assert (c.load(5), c.status(5)) == (0, False)
    assert counters.load(5) == 1  # the copies are independent


def test_banks_copy_and_pickle() -> None:
    n = 1500  # two chunks of the bank
    rng = np.random.default_rng(7)
    bank = plc_timers.TonBank(n)
    pt = rng.integers(0, 400, n).astype(np.int32)
    for k in range(5):
        bank.scan(100 * k, rng.integers(0, 2, n).astype(np.bool_), pt)
    copies = snapshots(bank)
    inputs = [rng.integers(0, 2, n).astype(np.bool_) for _ in range(5)]
    def scans(b: plc_timers.TonBank) -> List[Tuple[List[bool], List[int]]]:
        return [
            (q.tolist(), et.tolist())
            for k, i in enumerate(inputs)
            for q, et in [b.scan(500 + 100 * k, i, pt)]
        ]

    want = scans(bank)
    for c in copies:
        got = scans(c)
        assert got == want, "IEC-BANK-01: a copied bank differs from the original"
    counters = plc_timers.CounterBank(n, type="USINT")
    counters.scan(pv=2, cu=rng.integers(0, 2, n).astype(np.bool_))
    for c in snapshots(counters):
        assert c.type == "USINT" and len(c) == n
        assert [c.state(i) for i in range(0, n, 97)] == [counters.state(i) for i in range(0, n, 97)]


# --- threads ------------------------------------------------------------------------------------


class GivesTheGilAway:
    """Garbage whose collection runs Python code that lets another thread run: with the
    collector run at every allocation, a scan that allocates (its output arrays, its tuple)
    is interrupted there, as a program's finalizers may interrupt it at random."""

    def __init__(self) -> None:
        self.cycle = self

    def __del__(self) -> None:
        time.sleep(0)


def test_banks_shared_by_threads() -> None:
    """Four threads scanning one bank, interrupted inside their scans: every call runs (no
    'Already borrowed'), each scan whole."""
    n = 4096
    ton = plc_timers.TonBank(n)
    counters = plc_timers.CounterBank(n)
    ones, pt = np.ones(n, np.bool_), np.full(n, 10**6, np.int32)
    errors: List[BaseException] = []
    calls = [0]
    lock = threading.Lock()
    old = sys.getswitchinterval()
    thresholds = gc.get_threshold()
    sys.setswitchinterval(1e-6)
    gc.set_threshold(1, 1, 1)

    def work() -> None:
        try:
            for k in range(300):
                GivesTheGilAway()
                ton.scan(0, ones, pt)
                ton.output(k % n)
                counters.scan(pv=10**4, cu=ones if k % 2 else None)
                copy.copy(counters)
                with lock:
                    calls[0] += 1
        except BaseException as e:  # noqa: BLE001 - any failure is the test's finding
            errors.append(e)

    threads = [threading.Thread(target=work) for _ in range(4)]
    try:
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    finally:
        sys.setswitchinterval(old)
        gc.set_threshold(*thresholds)
    assert errors == [] and calls[0] == 1200
    q, et = ton.scan(0, ones, pt)
    assert not q.any() and not et.any()  # IN 1 since 0 ms, PT 1000 s, at 0 ms
    _, _, cv = counters.scan(pv=10**4)
    # 600 rising CU per thread's pattern at most; scans of the threads interleave, so the count
    # is the rising edges the bank saw: at least 1, at most the 600 scans that had CU = 1.
    assert 1 <= int(cv[0]) <= 600 and (cv == cv[0]).all()


# --- sizes, indices and names -------------------------------------------------------------------


@pytest.mark.parametrize(
    ("make", "error", "says"),
    [
        (lambda: plc_timers.TonBank(-1), ValueError, "n is the number of lanes, 1..="),
        (lambda: plc_timers.CounterBank(0), ValueError, "n is the number of lanes, 1..="),
        (lambda: plc_timers.TimerMemory(-64), ValueError, "count -64 is not an area size"),
        (lambda: plc_timers.CounterMemory(-1), ValueError, "count -1 is not an area size"),
        (lambda: plc_timers.TonBank(4).output(-1), IndexError, "no timer -1: this bank has 0 to 3"),
        (lambda: plc_timers.TonBank(4).output(4), IndexError, "no timer 4: this bank has 0 to 3"),
        (lambda: plc_timers.CounterBank(2).state(-2), IndexError, "no counter -2"),
        (lambda: plc_timers.TimerMemory(64).load(-1), ValueError, "index is an operand number"),
        (lambda: plc_timers.TimerMemory(64).tick(10, -1), ValueError, "n is a number of ticks"),
    ],
)
def test_negative_sizes_and_indices_say_what_is_allowed(
    make: Callable[[], Any], error: type, says: str
) -> None:
    with pytest.raises(error) as e:
        make()
    assert type(e.value) is error  # not pyo3's OverflowError
    assert says in str(e.value)


def test_all_names_public_and_present() -> None:
    assert all(hasattr(plc_timers, n) for n in plc_timers.__all__)
    private = [n for n in plc_timers.__all__ if n.startswith("_") and not n.endswith("__")]
    assert private == []


def test_type_aliases_exist_at_runtime() -> None:
    from plc_timers import Cell, CounterPresetLike, Row, S5TimeLike, TimeLike

    assert Time in TimeLike.__args__ and str in TimeLike.__args__  # type: ignore[attr-defined]
    assert S5Time in S5TimeLike.__args__  # type: ignore[attr-defined]
    assert CounterPreset in CounterPresetLike.__args__  # type: ignore[attr-defined]
    assert bool in Cell.__args__  # type: ignore[attr-defined]
    assert len(Row.__args__) == 2  # type: ignore[attr-defined]
