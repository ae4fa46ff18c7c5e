#!/usr/bin/env python3
"""bench/results.py on canned benchmark outputs (its --from mode): the rows of the groups read are
rewritten with their figures and verdicts, the other rows and the text around the table stay as
they were, and a malformed input fails with an error naming it and leaves RESULTS.md untouched."""

import argparse
import contextlib
import io
import json
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
import results  # noqa: E402
import ring_latency  # noqa: E402

OLD_ROW = ("| navigator.lobe | lobe tab query p99 <= 1 ms | 0.524 ms | met | 2026-12-06 10:00 "
           "| e83a27a | Intel(R) Xeon(R) Processor, 2 cores, load 0.3 -> 0.5 "
           "| `brdfnav bench navigator` |")
TABLE = f"""# Benchmark results

Before the table.

{results.BEGIN}
| id | target | figure | met | date | commit | machine | command |
|---|---|---|---|---|---|---|---|
{OLD_ROW}
| closures.eval.he | He eval | 79 ns | met | 2026-12-06 09:00 | 38b5aef | old CPU | `a \\| b` |
{results.END}

## How to read it

After the table.
"""
STAMP = {"date": "2026-12-07 08:00", "commit": "abc1234-dirty",
         "machine": "Test CPU, 2 cores, load 1.0 -> 2.0", "command": "bench host"}
RING = """http://127.0.0.1:1: radius 0.03, exact steps
| model | rings | preview median s | p95 s | max s | final median s | p95 s | max s |
|---|---:|---:|---:|---:|---:|---:|---:|
| blinn_phong | 12 | 0.042 | 0.144 | 0.144 | 1.68 | 2.02 | 2.24 |
| ward | 12 | 0.047 | 0.079 | 0.137 | 0.30 | 0.40 | 0.45 |

| tab | rings | rings without a render | final median s | p95 s | max s |
|---|---:|---:|---:|---:|---:|
| lobe | 6 | 6 | 0.11 | 9.50 | 9.50 |
"""


def benchmark(model, ns):
    return {"run_name": f"BM_Eval/{model}", "aggregate_name": "median", "cpu_time": ns,
            "time_unit": "ns"}


class Results(unittest.TestCase):
    def setUp(self):
        self.dir = Path(tempfile.mkdtemp())
        self.saved = self.dir / "saved"
        self.saved.mkdir()
        self.md = self.dir / "RESULTS.md"
        self.md.write_text(TABLE)
        self.put("host.json", {"bench": "host", "figures": {
            "libraries": 8, "wall_median_ms": 45.5, "wall_p90_ms": 50, "peak_rss_mib": 4.3}})
        self.put("closures.benchmark.json", {"benchmarks": [
            benchmark(m, 30.0) for m in ("blinn_phong", "ward", "cook_torrance", "lafortune",
                                         "ggx")] + [benchmark("he", 1200.0)]})
        self.put("ring.memory.json", {"rss_start_mib": 150, "rss_mid_mib": 200,
                                      "rss_end_mib": 210})
        (self.saved / "ring.txt").write_text(RING)
        for group in ("host", "closures", "ring"):
            self.put(f"{group}.stamp.json", STAMP)

    def put(self, name, value):
        (self.saved / name).write_text(json.dumps(value))

    def main(self, *names):
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            status = results.main([*names, "--from", str(self.saved), "--results", str(self.md)])
        return status, err.getvalue()

    def row(self, id):
        _, rows, _ = results.read_table(self.md)
        return rows[id]

    def test_rewrites_the_rows_read_and_keeps_the_others(self):
        status, err = self.main("host", "closures", "ring")
        self.assertEqual(status, 0, err)
        text = self.md.read_text()
        self.assertIn("Before the table.", text)
        self.assertIn("After the table.", text)
        self.assertIn(OLD_ROW, text)  # navigator: not read, kept byte for byte
        self.assertEqual(self.row("host.libraries")[2:4], ["8", "met"])
        self.assertEqual(self.row("host.wall")[2:], [
            "45.5 ms", "**not met**", "2026-12-07 08:00", "abc1234-dirty",
            "Test CPU, 2 cores, load 1.0 -> 2.0", "`bench host`"])
        self.assertEqual(self.row("host.rss")[2], "4.51 MB")
        self.assertEqual(self.row("closures.eval.he")[2:4], ["1.2e+03 ns", "**not met**"])
        self.assertEqual(self.row("closures.eval.ward")[2:4], ["30 ns", "met"])
        self.assertEqual(self.row("ring.preview")[2:4], ["0.144 s (blinn_phong)", "met"])
        self.assertEqual(self.row("ring.final")[2:4], ["2.020 s (blinn_phong)", "**not met**"])
        # Every target has a row, in the script's order; the ones never run say so.
        _, rows, _ = results.read_table(self.md)
        self.assertEqual(list(rows), [t.id for t in results.TARGETS])
        self.assertEqual(rows["render.ward"][2:4], ["not measured yet", "-"])

    def test_render_and_fidelity_figures(self):
        render = {f"{m}_alone_ms": 150.0 for m in results.MODELS}
        render.update({f"{m}_max_ratio": 0.05 for m in results.MODELS})
        render.update({"he_alone_ms": 330.0, "he_batched_ms": 95.0, "ward_grid_ms": 80.0,
                       "ggx_alone_ms": 900.0, "lafortune_max_ratio": 0.12})
        self.put("render.json", {"bench": "render", "figures": render})
        fidelity = {}
        for m in results.MODELS:
            fidelity.update({f"{m}_final_median_eps": 0.01, f"{m}_final_worst_eps": 0.02})
            for tab in ("lobe", "diffuse", "specular"):  # no models tab: no unflagged offer
                fidelity.update({f"{m}_{tab}_step_median": 0.01, f"{m}_{tab}_step_p90": 0.02})
        fidelity.update({"he_lobe_step_median": 0.056, "he_specular_step_p90": 0.09,
                         "lafortune_final_worst_eps": 21.7})
        self.put("fidelity.json", {"bench": "fidelity", "figures": fidelity})
        for group in ("render", "fidelity"):
            self.put(f"{group}.stamp.json", STAMP)
        self.assertEqual(self.main("render", "fidelity")[0], 0)
        self.assertEqual(self.row("render.he")[2:4], ["95 ms (alone 330 ms)", "met"])
        self.assertEqual(self.row("render.ward")[2:4], ["80 ms (alone 150 ms)", "met"])
        self.assertEqual(self.row("render.ggx")[2:4], ["900 ms", "**not met**"])
        self.assertEqual(self.row("render.accuracy")[2:4], ["0.120 (lafortune)", "**not met**"])
        self.assertEqual(self.row("fidelity.thumbnails.lafortune")[2:4],
                         ["0.010 / 21.700 eps", "**not met**"])
        self.assertEqual(self.row("fidelity.steps.he")[2:4],
                         ["worst tab lobe: 5.6 % / 2.0 %", "**not met**"])
        self.assertEqual(self.row("fidelity.steps.ward")[2:4],
                         ["worst tab lobe: 1.0 % / 2.0 %", "met"])
        self.assertEqual(self.row("render320.ward")[2], "not measured yet")

    def test_a_pipe_in_a_cell_survives_the_round_trip(self):
        self.assertEqual(self.main("host")[0], 0)
        self.assertEqual(self.row("closures.eval.he")[7], "`a | b`")
        self.assertIn("`a \\| b`", self.md.read_text())

    def test_a_filter_keeps_the_rows_of_benchmarks_it_left_out(self):
        self.put("closures.benchmark.json", {"benchmarks": [benchmark("ward", 20.0)]})
        self.assertEqual(self.main("closures", "--filter", "ward")[0], 0)
        self.assertEqual(self.row("closures.eval.ward")[2], "20 ns")
        self.assertEqual(self.row("closures.eval.he")[2:5], ["79 ns", "met", "2026-12-06 09:00"])

    def test_a_skipped_group_keeps_its_row(self):
        (self.saved / "ring8.skipped").write_text("no --clients\n")
        self.assertEqual(self.main("ring8", "host")[0], 0)
        self.assertEqual(self.row("ring.clients8")[2:4], ["not measured yet", "-"])

    def test_eight_clients_memory_is_flat_when_its_second_half_stays(self):
        (self.saved / "ring8.txt").write_text(RING.replace("2.02", "1.50"))
        self.put("ring8.stamp.json", STAMP)
        self.put("ring8.memory.json", {"rss_start_mib": 150, "rss_mid_mib": 400,
                                       "rss_end_mib": 430})
        self.assertEqual(self.main("ring8")[0], 0)
        self.assertEqual(self.row("ring.clients8")[2:4],
                         ["1.50 s (blinn_phong); server RSS 150 -> 400 -> 430 MiB", "met"])
        self.put("ring8.memory.json", {"rss_start_mib": 150, "rss_mid_mib": 400,
                                       "rss_end_mib": 450})
        self.assertEqual(self.main("ring8")[0], 0)
        self.assertEqual(self.row("ring.clients8")[3], "**not met**")

    def assert_refused(self, names, *words):
        before = self.md.read_bytes()
        status, err = self.main(*names)
        self.assertEqual(status, 1, err)
        for word in words:
            self.assertIn(word, err)
        self.assertEqual(self.md.read_bytes(), before)
        self.assertEqual(sorted(p.name for p in self.dir.iterdir()), ["RESULTS.md", "saved"])

    def test_malformed_json_is_refused_naming_the_file(self):
        (self.saved / "host.json").write_text('{"figures": {"libraries": 8,')
        self.assert_refused(["closures", "host"], "host.json", "not JSON")

    def test_a_missing_figure_is_refused_naming_it(self):
        self.put("host.json", {"figures": {"libraries": 8, "peak_rss_mib": 4.0}})
        self.assert_refused(["host"], "host.wall", "wall_median_ms")

    def test_a_figure_that_is_not_a_number_is_refused(self):
        self.put("host.json", {"figures": {"libraries": "eight", "wall_median_ms": 1,
                                           "peak_rss_mib": 4.0}})
        self.assert_refused(["host"], "libraries", "not a number")

    def test_a_missing_output_is_refused(self):
        (self.saved / "ring.txt").unlink()
        self.assert_refused(["ring"], "ring.txt", "missing")

    def test_a_malformed_ring_table_is_refused_naming_its_row(self):
        (self.saved / "ring.txt").write_text(RING.replace("0.079", "fast"))
        self.assert_refused(["ring"], "ring.txt", "table row 4")

    def test_a_malformed_table_row_is_refused_naming_its_line(self):
        self.md.write_text(TABLE.replace(OLD_ROW, "| navigator.lobe | too few |"))
        self.assert_refused(["host"], "RESULTS.md:8", "2 cells")

    def test_an_unknown_row_or_name_is_refused(self):
        self.md.write_text(TABLE.replace("| navigator.lobe |", "| navigator.gone |"))
        self.assert_refused(["host"], "RESULTS.md:8", "navigator.gone")
        self.md.write_text(TABLE)
        self.assert_refused(["hots"], "'hots'")

    def test_missing_markers_are_refused(self):
        self.md.write_text(TABLE.replace(results.END, ""))
        self.assert_refused(["host"], "RESULTS.md", results.END)


class RingLatencyFractions(unittest.TestCase):
    """ring_latency.py --fractions: numbers in [0, 1], refused otherwise with what was given."""

    def test_reads_numbers_between_zero_and_one(self):
        self.assertEqual(ring_latency.fractions("0.1,0.5,1"), (0.1, 0.5, 1.0))

    def test_refuses_anything_else_naming_it(self):
        for text in ("0.1,2", "a,b", "", "-0.1"):
            with self.assertRaises(argparse.ArgumentTypeError) as refused:
                ring_latency.fractions(text)
            self.assertIn(repr(text), str(refused.exception))


if __name__ == "__main__":
    unittest.main()
