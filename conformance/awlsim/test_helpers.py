"""Unit tests of the runner's own helpers: the virtual clock, the STL programs, the presets,
the adapter's reading of `check`, and awlsim driven through them on cases whose outputs follow
from the manuals' definitions (independent of the reference)."""

import unittest

import awl
import deviations
import program
import reference
import traces
from awlsim.awlcompiler.tokenizer import AwlParser
from awlsim.common.sources import AwlSource


class ClockTest(unittest.TestCase):
    def test_awlsims_millisecond_conversion_reads_t_ms(self):
        # awlsim: now_TIME = int(now * 1000.0) & 0x7FFFFFFF. 1001 ms is one of the values
        # that t / 1000 alone would turn into 1000.
        c = program.VirtualClock()
        for t in [0, 1, 1001, 1003, 2**31 - 1, 2**31, 2**32 + 7, 16881492525]:
            c.set(t)
            self.assertEqual(int(c() * 1000.0), t)
        self.assertEqual(int((1001 / 1000) * 1000.0), 1000)  # why the offset is there

    def test_clock_never_goes_back(self):
        c = program.VirtualClock()
        c.set(10)
        with self.assertRaises(ValueError):
            c.set(9)


class ProgramTest(unittest.TestCase):
    def test_every_program_parses_and_uses_its_operation(self):
        for block in traces.BLOCKS:
            src = program.stl(block)
            p = AwlParser()
            p.parseSource(AwlSource(name=block, sourceBytes=src.encode()))
            self.assertEqual(len(p.getParseTree().obs), 1, block)
            if block in program.S5_TIMER_OPS:
                self.assertIn(f"\t{program.S5_TIMER_OPS[block]} T 1\n", src)
            elif block in program.IEC_SFBS:
                self.assertIn(f"CALL SFB {program.IEC_SFBS[block]}, DB", src)
            else:
                self.assertIn("\tS C 1\n", src)

    def test_blocks_awlsim_lacks_are_an_error(self):
        with self.assertRaisesRegex(ValueError, "no counterpart of 'TONR'"):
            program.layout("TONR")

    def test_counter_presets(self):
        self.assertEqual(program.counter_preset_word("C#123"), 0x123)
        self.assertEqual(program.counter_preset_word("999"), 0x999)
        self.assertEqual(program.counter_preset_word("W#16#0042"), 0x42)
        with self.assertRaises(ValueError):
            program.counter_preset_word("C#1000")


class AwlsimTest(unittest.TestCase):
    def test_ton_on_the_virtual_clock(self):
        # TON: ET = now - start, Q once ET reaches PT (S7-1200 manual); IN at 5 ms, PT 30 ms.
        rows = [{"t_ms": t, "IN": i, "PT": 30} for t, i in [(0, 0), (5, 1), (20, 1), (35, 1)]]
        out = awl.run("TON", rows)
        self.assertEqual([(o["Q"], o["ET"]) for o in out],
                         [(False, 0), (False, 0), (False, 15), (True, 30)])

    def test_ctu_counts_rising_edges(self):
        rows = [{"CU": c, "R": 0, "PV": 2} for c in [1, 1, 0, 1, 0, 1]]
        self.assertEqual([o["CV"] for o in awl.run("CTU", rows)], [1, 1, 1, 2, 2, 3])

    def test_s5_counter_words(self):
        rows = [{"CU": 0, "S": 1, "R": 0, "PV": "C#12"}, {"CU": 1, "S": 1, "R": 0, "PV": "C#12"}]
        out = awl.run("S_CU", rows)
        self.assertEqual((out[1]["CV"], out[1]["CV_BCD"], out[1]["Q"]), (13, 0x13, True))


class AdapterTest(unittest.TestCase):
    def test_check_names_line_column_and_rules(self):
        # spec/cli.md: a BI that misses the tick at 10 ms differs at that row, by S5TMR-TICK-01.
        rows = [{"t_ms": 0, "S": 0, "R": 0, "TV": "S5T#50MS", "Q": 0, "BI": 0, "BCD": 0},
                {"t_ms": 5, "S": 1, "R": 0, "TV": "S5T#50MS", "Q": 1, "BI": 5, "BCD": 5},
                {"t_ms": 16, "S": 1, "R": 0, "TV": "S5T#50MS", "Q": 1, "BI": 5, "BCD": 5}]
        d = reference.check("S_PULSE", rows)
        self.assertIsNotNone(d)
        self.assertEqual((d.line, d.column, d.output), (4, 6, "BI"))
        self.assertIn("S5TMR-TICK-01", d.rules)
        rows[2].update(BI=4, BCD=4)
        self.assertIsNone(reference.check("S_PULSE", rows))

    def test_the_command_and_the_package_name_the_same_rules(self):
        # The command's text, read by the fallback, gives what the package's fields give (the
        # command does not repeat at the earlier row a rule named at the row). The earlier row
        # is the latest that wrote ET: the start.
        rows = [{"t_ms": 0, "IN": 1, "PT": "T#500ms", "Q": 0, "ET": 0},
                {"t_ms": 200, "IN": 1, "PT": "T#500ms", "Q": 0, "ET": 201}]
        cli = reference._cli_check("TON", rows, tv=None, pt=None, pv=None, type="INT",
                                   optimized=False)
        self.assertEqual((cli.line, cli.output, cli.earlier_line), (3, "ET", 2))
        self.assertTrue(cli.rules and cli.earlier_rules)
        d = reference.check("TON", rows)
        self.assertEqual((d.line, list(d.rules), d.earlier_line), (cli.line, cli.rules, 2))
        self.assertEqual([r for r in d.earlier_rules if r not in d.rules], cli.earlier_rules)

    def test_literals(self):
        self.assertEqual(reference.s5time_word("S5T#2M7S"), 0x2127)  # LAD manual, Fig. 9-1
        self.assertEqual(reference.s5time_word("W#16#2001"), 0x2001)  # as written
        self.assertEqual(reference.time_ms("T#2s_200ms"), 2200)


class TracesTest(unittest.TestCase):
    def test_a_vector_is_run_up_to_its_first_rt_row(self):
        # awlsim's SFBs have no -(RT)- coil: the rows from the first RT = 1 on are not run, and
        # the column is dropped (RT = 0 rows are the box alone).
        rows = [{"t_ms": 0, "IN": 1, "RT": 0}, {"t_ms": 5, "IN": 1, "RT": 0},
                {"t_ms": 9, "IN": 1, "RT": 1}, {"t_ms": 12, "IN": 1, "RT": 0}]
        self.assertEqual(traces.before_coil(rows),
                         [{"t_ms": 0, "IN": 1}, {"t_ms": 5, "IN": 1}])
        self.assertEqual(traces.before_coil([{"t_ms": 0, "IN": 1}]), [{"t_ms": 0, "IN": 1}])


class ShrinkTest(unittest.TestCase):
    def test_a_padded_trace_shrinks_to_its_core(self):
        import runner
        # TON with PT raised from 10 to 50 ms while running: the reference keeps 10 ms
        # (IEC-PT-LATCH-01), awlsim reads 50 live; rows of IN = 0 before it are padding.
        rows = [{"t_ms": t, "IN": 0, "PT": 10} for t in range(0, 50, 5)]
        rows += [{"t_ms": 60, "IN": 1, "PT": 10}, {"t_ms": 65, "IN": 1, "PT": 50},
                 {"t_ms": 75, "IN": 1, "PT": 50}, {"t_ms": 90, "IN": 1, "PT": 50}]
        got, _want, first, _n = runner.first_difference("TON", rows)
        self.assertEqual(first, len(rows) - 2)  # at 75 ms: the reference's Q rises
        d = runner.explain("TON", rows, got)
        key = runner.group_key(runner.classify("TON", rows, got, d))
        self.assertEqual(key, ("IEC-PT-LATCH-01", None))
        small = runner.shrink("TON", rows, key)
        self.assertLessEqual(len(small), 3)
        self.assertEqual(small[-1]["t_ms"], 75)


class DeviationsTest(unittest.TestCase):
    def test_every_entry_cites_an_awlsim_paragraph(self):
        self.assertEqual(deviations.verify(reference.REPO), [])

    def test_entries_do_not_accept_an_unrelated_difference(self):
        # A CTU that counts wrong is no documented deviation.
        case = deviations.Case("CTU", [{"CU": 1, "R": 0, "PV": 3}], [{"Q": False, "CV": 2}],
                               [{"Q": False, "CV": 1}], "CV", ("CNT-EDGE-01",))
        self.assertIsNone(deviations.classify(case))

    def test_a_named_set_alone_is_not_the_set_deviation(self):
        # S_CU set to 5 with CU = 0, CU rises two rows later: awlsim counting 2 would be no
        # documented deviation, though check names the set at the earlier row.
        rows = [{"CU": 0, "S": 1, "R": 0, "PV": "C#5"}, {"CU": 0, "S": 0, "R": 0, "PV": "C#5"},
                {"CU": 1, "S": 0, "R": 0, "PV": "C#5"}]
        case = deviations.Case("S_CU", rows, [{"Q": True, "CV": 7}] * 3,
                               [{"Q": True, "CV": 6}] * 3, "CV", ("SC-EDGE-01",),
                               ("SC-SET-01",), 0)
        self.assertIsNone(deviations.classify(case))
        held = [{**r, "CU": 1} for r in rows]  # CU held through the set: the deviation
        case = deviations.Case("S_CU", held, case.got, case.want, "CV", ("SC-EDGE-01",),
                               ("SC-SET-01",), 0)
        self.assertEqual(deviations.classify(case).rule, "SC-SET-01")

    def lc_case(self, got_bcd, want_bcd, bi=3):
        row = {"t_ms": 0, "S": 1, "R": 0, "TV": "W#16#2005"}
        return deviations.Case("S_PULSE", [row], [{"Q": True, "BI": bi, "BCD": got_bcd}],
                               [{"Q": True, "BI": bi, "BCD": want_bcd}], "BCD",
                               ("S5TMR-RANGE-01",))

    def test_lc_entry_takes_only_the_two_measured_forms(self):
        ok = deviations.classify(self.lc_case(0x2003, 0x2004, bi=4))  # 1 s base, one unit
        self.assertEqual(ok.rule, "S5TMR-LOAD-01")
        kept = deviations.classify(self.lc_case(0x2000, 0x0000, bi=0))  # base kept after R
        self.assertEqual(kept.rule, "S5TMR-LOAD-01")
        self.assertIsNone(deviations.classify(self.lc_case(0x2002, 0x2004, bi=4)))  # two units
        half = deviations.classify(self.lc_case(0x0012, 0x0011, bi=11))  # 10 ms, L and LC apart
        self.assertEqual(half.name, "S5TMR-LOAD-01 (half unit)")
        self.assertIsNone(deviations.classify(self.lc_case(0x0013, 0x0011, bi=11)))  # two units


if __name__ == "__main__":
    unittest.main()
