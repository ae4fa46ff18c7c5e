#!/usr/bin/env python3
"""Runs brdfnav's benchmarks and rewrites the table of targets at the top of bench/RESULTS.md.

    bench/results.py [--build DIR] [--db DIR] [--slow] [--filter REGEX] [NAME ...]

NAME is a group (host, closures, render, ...) or one target's id (closures.eval.ward); none means
every group but the slow ones (--slow adds them). Each group's command writes its figures to
BUILD/bench-results/GROUP.* with a stamp (date, commit, machine, command); then only the rows of
the chosen targets are replaced, the others keep their own date and commit. --from DIR reads the
outputs a run saved there instead of running anything (how the test drives it, and how a run that
failed part way is recovered). Any error (a command that fails, an output that lacks a figure, a
malformed table) names its file and leaves bench/RESULTS.md as it was.

Python, not a `brdfnav bench all`: the runner starts processes (the CLI, Google Benchmark,
`brdfnav serve` with bench/ring_latency.py, which is Python already), reads their JSON, asks git
and lscpu, and edits Markdown; none of that belongs in the library or needs a rebuild to change.
Standard library only, so it runs wherever python3 does.
"""

import argparse
import datetime
import json
import os
import re
import shlex
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BEGIN, END = "<!-- results:begin -->", "<!-- results:end -->"
HEADER = ["id", "target", "figure", "met", "date", "commit", "machine", "command"]
MODELS = ["blinn_phong", "ward", "cook_torrance", "lafortune", "he", "ggx"]
TABS = ["lobe", "diffuse", "specular", "models"]
MB_PER_MIB = 1.048576


class BenchError(Exception):
    """An error that names the file (and key or line) it is about."""


# ---------------------------------------------------------------------------------------------
# The targets: one place for every threshold. Each target reads figures from its group's output
# (a dict of name -> number) and returns (figure text, met?).


def below(key, limit, unit, scale=1.0, digits=3, fmt=None):
    """The figure `key` (times `scale`) against `<= limit`, shown by `fmt` if given."""

    def check(f):
        value = need(f, key) * scale
        shown = fmt(value) if fmt else f"{value:.{digits}g} {unit}".strip()
        return shown, value <= limit

    return check


def worst_of(keys_limits, fmt):
    """Several figures each against its limit: met when all are; shows every figure."""

    def check(f):
        values = [need(f, key) for key, _ in keys_limits]
        met = all(v <= limit for v, (_, limit) in zip(values, keys_limits))
        return fmt(*values), met

    return check


def render_speed(model, limit_ms):
    """Mean ms per image as the precompute renders it: Ward's grid in one pass, He's and
    Cook-Torrance's along their Fresnel parameter, the others one by one; alone beside it."""

    def check(f):
        alone = need(f, f"{model}_alone_ms")
        key = {"ward": "ward_grid_ms"}.get(model, f"{model}_batched_ms")
        value = f.get(key, alone)
        shown = f"{value:.0f} ms" + (f" (alone {alone:.0f} ms)" if key in f else "")
        return shown, value <= limit_ms

    return check


def largest_ratio(limit):
    """The largest accuracy ratio over every model, setting and parameter."""

    def check(f):
        ratios = {m: need(f, f"{m}_max_ratio") for m in MODELS}
        model = max(ratios, key=ratios.get)
        return f"{ratios[model]:.3f} ({model})", ratios[model] <= limit

    return check


def steps(model, median, p90):
    """|rendered / eps - 1| of a model's offers over its tabs against (median, p90); a tab
    without unflagged offers (GGX has no models tab) has no figure."""

    def check(f):
        worst = None
        for tab in TABS:
            key = f"{model}_{tab}_step"
            if key + "_median" not in f:
                continue
            m, p = need(f, key + "_median"), need(f, key + "_p90")
            if worst is None or max(m / median, p / p90) > max(worst[1] / median, worst[2] / p90):
                worst = (tab, m, p)
        if worst is None:
            raise BenchError(f"no step figure of {model}")
        tab, m, p = worst
        return f"worst tab {tab}: {100 * m:.1f} % / {100 * p:.1f} %", m <= median and p <= p90

    return check


def ring(column, limit):
    def check(f):
        model = max(MODELS, key=lambda m: f.get(f"{m}_{column}_p95", -1))
        value = need(f, f"{model}_{column}_p95")
        return f"{value:.3f} s ({model})", value <= limit

    return check


def ring_clients(limit_s, growth):
    """The slowest model's final p95 against `limit_s`, and the server's memory: flat when it
    grows by at most `growth` over the run's second half (ring_latency.py's samples: a cache
    filling up grows at first and then stays; a leak keeps growing)."""

    def check(f):
        model = max(MODELS, key=lambda m: f.get(f"{m}_final_p95", -1))
        p95 = need(f, f"{model}_final_p95")
        start, mid, end = need(f, "rss_start_mib"), need(f, "rss_mid_mib"), need(f, "rss_end_mib")
        met = p95 <= limit_s and end <= growth * mid
        return f"{p95:.2f} s ({model}); server RSS {start:.0f} -> {mid:.0f} -> {end:.0f} MiB", met

    return check


class Target:
    def __init__(self, id, group, text, check, pending="not measured yet"):
        self.id, self.group, self.text, self.check = id, group, text, check
        self.pending = pending  # the figure shown until the first run


def render_targets(group, px, limit_ms):
    return [Target(f"{group}.{m}", group, f"{m}: ms per image at {px} px <= {limit_ms} ms",
                   render_speed(m, limit_ms)) for m in MODELS]


def minutes(seconds):
    return f"{seconds // 60:.0f} min {seconds % 60:.0f} s"


TARGETS = [
    Target("host.libraries", "host", "a host's shared libraries (`ldd`) <= 12",
           below("libraries", 12, "", digits=3)),
    Target("host.wall", "host", "a host's wall time, median <= 30 ms",
           below("wall_median_ms", 30, "ms")),
    Target("host.rss", "host", "a host's peak RSS <= 12 MB",
           below("peak_rss_mib", 12, "MB", scale=MB_PER_MIB)),
] + [
    Target(f"closures.eval.{m}", "closures", f"{m} closure eval <= {limit} ns",
           below(f"eval_{m}_ns", limit, "ns"))
    for m, limit in [("blinn_phong", 50), ("ward", 50), ("cook_torrance", 50), ("lafortune", 50),
                     ("he", 1000), ("ggx", 50)]
] + render_targets("render", 128, 200) + [
    Target("render.accuracy", "render", "accuracy ratio at 128 px <= 0.10, every setting",
           largest_ratio(0.10)),
] + render_targets("render320", 320, 1000) + [
    Target("accuracy320", "accuracy320", "accuracy ratio at 320 px <= 0.10, every setting (slow)",
           largest_ratio(0.10)),
    Target("fits", "fits", "conversion fit, mean <= 20 ms (one thread)",
           below("mean_ms_per_fit", 20, "ms")),
    Target("precompute.default.time", "precompute", "default profile build <= 5 min",
           below("wall_s", 300, "s", fmt=minutes)),
    Target("precompute.default.memory", "precompute", "default profile peak RSS <= 8 GB",
           below("peak_rss_mib", 8000, "MB", scale=MB_PER_MIB)),
    Target("precompute.paper.time", "paper", "paper profile build <= 20 min (slow)",
           below("wall_s", 1200, "s", fmt=minutes)),
    Target("precompute.paper.memory", "paper", "paper profile peak RSS <= 8 GB (slow)",
           below("peak_rss_mib", 8000, "MB", scale=MB_PER_MIB)),
    Target("embedding", "embedding",
           "embedded vs exact distance, median <= 1 %, p95 <= 3 % (slow)",
           worst_of([("median", 0.01), ("p95", 0.03)],
                    lambda m, p: f"{100 * m:.2f} % / {100 * p:.2f} %")),
    Target("navigator.lobe", "navigator", "lobe tab query p99 <= 1 ms",
           below("lobe_p99_ms", 1, "ms")),
    Target("navigator.models", "navigator", "models tab query p99 <= 10 ms",
           below("models_p99_ms", 10, "ms")),
    Target("navigator.thumbnails", "navigator",
           "10 thumbnails through OCIO, p99 <= 250 ms (first view / cached)",
           worst_of([("thumbnails_first_p99_ms", 250), ("thumbnails_cached_p99_ms", 250)],
                    lambda a, b: f"{a:.0f} / {b:.0f} ms")),
    Target("navigator.memory", "navigator", "resident memory, database open <= 200 MB",
           below("rss_open_mib", 200, "MB", scale=MB_PER_MIB)),
] + [
    Target(f"fidelity.thumbnails.{m}", "fidelity",
           f"{m}: final images vs exact <= 0.05 eps median, 0.25 worst",
           worst_of([(f"{m}_final_median_eps", 0.05), (f"{m}_final_worst_eps", 0.25)],
                    lambda a, b: f"{a:.3f} / {b:.3f} eps")) for m in MODELS
] + [
    Target(f"fidelity.steps.{m}", "fidelity",
           f"{m}: embedding's steps within 5 % median, 10 % p90 of eps", steps(m, 0.05, 0.10))
    for m in MODELS
] + [
    Target(f"fidelity.exact.{m}", "fidelity-exact",
           f"{m}: exact steps within 5 % median, 10 % p90 of eps", steps(m, 0.05, 0.10))
    for m in MODELS
] + [
    Target("ring.preview", "ring", "a ring's previews, p95 <= 150 ms (worst model)",
           ring("preview", 0.150)),
    Target("ring.final", "ring", "a ring's final images, p95 <= 500 ms (worst model)",
           ring("final", 0.500)),
    Target("ring.clients8", "ring8",
           "8 clients: final p95 <= 2 s, flat server memory (+10 % at most over the second half)",
           ring_clients(2.0, 1.10), pending="not measured yet"),
]
BY_ID = {t.id: t for t in TARGETS}
SLOW = {"accuracy320", "paper", "embedding"}
GROUPS = list(dict.fromkeys(t.group for t in TARGETS))


def need(figures, key):
    if key not in figures:
        raise BenchError(f"no figure '{key}'")
    value = figures[key]
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        raise BenchError(f"figure '{key}' is not a number: {value!r}")
    return float(value)


# ---------------------------------------------------------------------------------------------
# Running a group: its command(s), whose figures land in OUT/GROUP.json, and OUT/GROUP.stamp.json.


def run(cmd, **kwargs):
    print("+ " + shlex.join(cmd), file=sys.stderr, flush=True)
    result = subprocess.run(cmd, **kwargs)
    if result.returncode != 0:
        raise BenchError(f"{shlex.join(cmd)}: exit status {result.returncode}")
    return result


def timed_rusage(cmd):
    """Wall seconds and peak resident MiB of `cmd` and its children (wait4's ru_maxrss)."""
    print("+ " + shlex.join(cmd), file=sys.stderr, flush=True)
    start = time.monotonic()
    process = subprocess.Popen(cmd)
    _, status, usage = os.wait4(process.pid, 0)
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise BenchError(f"{shlex.join(cmd)}: exit status {process.returncode}")
    return time.monotonic() - start, usage.ru_maxrss / 1024.0


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def ring_run(cli, db, extra, out_txt):
    """bench/ring_latency.py --exact against a fresh `brdfnav serve`: its output, and its figures
    of the server's memory (its --json line)."""
    port = free_port()
    serve = subprocess.Popen([cli, "serve", "--db", db, "--port", str(port)],
                             stdout=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}"
    try:
        for _ in range(600):
            try:
                urllib.request.urlopen(url + "/api/info").read()
                break
            except OSError:
                if serve.poll() is not None:
                    raise BenchError(f"{cli} serve --db {db}: exited with {serve.returncode}")
                time.sleep(0.5)
        cmd = [sys.executable, str(ROOT / "bench/ring_latency.py"), "--url", url, "--exact",
               "--server-pid", str(serve.pid), "--json", *extra]
        result = run(cmd, stdout=subprocess.PIPE, text=True)
        out_txt.write_text(result.stdout)
        print(result.stdout, end="")
        try:
            summary = json.loads(result.stdout.splitlines()[-1])
        except (IndexError, json.JSONDecodeError):
            raise BenchError(f"{shlex.join(cmd)}: no JSON line at the end of its output") from None
        return {k: v for k, v in summary.items() if k.endswith("_mib") or k.endswith("_min")}
    finally:
        serve.terminate()
        serve.wait()


def run_group(group, args, out):
    """Runs `group`'s benchmark; returns the command to show in the table, or None when the
    group cannot run here yet (its rows stay as they are)."""
    b, cli = Path(args.build), str(Path(args.build) / "bin/brdfnav")
    figures_path = out / f"{group}.json"
    if group == "host":
        cmd = [str(b / "bin/brdfnav_bench_host"), "--json", str(figures_path),
               str(b / "bin/brdfnav_bench_host_one_closure"), "50"]
        run(cmd)
    elif group == "closures":
        cmd = [str(b / "bin/brdfnav_bench"), f"--benchmark_filter={args.filter or 'BM_Eval/'}",
               "--benchmark_repetitions=3", "--benchmark_report_aggregates_only=true",
               f"--benchmark_out={out / 'closures.benchmark.json'}", "--benchmark_out_format=json"]
        run(cmd)
    elif group in ("render", "render320", "accuracy320"):
        res = "128" if group == "render" else "320"
        cmd = [cli, "bench", "render", "--res", res, "--repeats", "2" if res == "128" else "1",
               "--json", str(figures_path)]
        if group == "render320":
            cmd.append("--no-accuracy")
        run(cmd)
    elif group == "fits":
        cmd = [cli, "bench", "fits", "--json", str(figures_path)]
        run(cmd)
    elif group in ("precompute", "paper"):
        profile = "default" if group == "precompute" else "paper"
        with tempfile.TemporaryDirectory(dir=out) as tmp:
            cmd = [cli, "precompute", "--profile", profile, "--out", f"{tmp}/db"]
            wall, peak = timed_rusage(cmd)
        cmd[-1] = "DB"
        write_json(figures_path, {"wall_s": wall, "peak_rss_mib": peak})
    elif group == "embedding":
        with tempfile.TemporaryDirectory(dir=out) as tmp:
            cmd = [cli, "validate", "--db", args.db, "--res", "128", "--pairs", "500", "--out", tmp]
            run(cmd)
            write_json(figures_path, embedding_figures(Path(tmp) / "report.yaml"))
        cmd[-1] = "DIR"
    elif group in ("navigator", "fidelity", "fidelity-exact"):
        cmd = [cli, "bench", group.split("-")[0], "--db", args.db, "--json", str(figures_path)]
        cmd += ["--materials", "40"] if group == "navigator" else ["--materials", "4"]
        cmd += ["--exact"] if group == "fidelity-exact" else []
        run(cmd)
    elif group in ("ring", "ring8"):
        # 8 pages, each through every model's and tab's rings at nine places along the grids
        # (1,728 in all): more lobes than the server's caches hold, so that they evict, and long
        # enough for the memory's second half to tell a leak from a cache filling up.
        extra = [] if group == "ring" else [
            "--clients", "8", "--fractions", ",".join(f"0.{i}" for i in range(1, 10))]
        memory = ring_run(cli, args.db, extra, out / f"{group}.txt")
        write_json(out / f"{group}.memory.json", memory)
        return shlex.join(["bin/brdfnav", "serve", "--db", "DB"]) + " & " + shlex.join(
            ["bench/ring_latency.py", "--exact", *extra])
    else:
        raise AssertionError(group)
    # As the table shows it: the build directory left out, the database named DB.
    return shlex.join(["DB" if c == args.db else c for c in cmd]).replace(str(b) + "/", "")


def write_json(path, value):
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps(value, indent=1) + "\n")
    tmp.replace(path)


def stamp(args):
    """Date, commit (with -dirty when tracked files differ from it), machine and load now."""
    git = ["git", "-C", str(ROOT)]
    commit = subprocess.run(git + ["rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "unknown"
    dirty = subprocess.run(git + ["status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    model = "unknown CPU"
    lscpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    for line in lscpu.splitlines():
        if line.startswith("Model name:"):
            model = line.split(":", 1)[1].strip()
    return {"date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M"),
            "commit": commit + ("-dirty" if dirty else ""),
            "machine": f"{model}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}"}


# ---------------------------------------------------------------------------------------------
# Reading a group's saved output back as figures.


def read_json(path):
    try:
        return json.loads(read_text(path))
    except json.JSONDecodeError as e:
        raise BenchError(f"{path}:{e.lineno}: not JSON: {e.msg}") from None


def embedding_figures(report):
    """The embedding's error at the most coefficients, from `validate`'s report.yaml (flow
    mappings `- {coefficients: K, median: M, p95: P}` under embedding: anywhere:)."""
    text = report.read_text()
    block = re.search(r"^embedding:\n  pairs: \d+\n  anywhere:\n((?:    - \{.*\}\n)+)", text, re.M)
    if not block:
        raise BenchError(f"{report}: no embedding: anywhere: list")
    rows = re.findall(r"coefficients: (\d+), median: ([0-9.e+-]+), p95: ([0-9.e+-]+)",
                      block.group(1))
    k, median, p95 = max(rows, key=lambda r: int(r[0]))
    return {"coefficients": int(k), "median": float(median), "p95": float(p95)}


def closure_figures(path):
    figures = {}
    for b in read_json(path).get("benchmarks", []):
        if b.get("aggregate_name") == "median" and b.get("run_name", "").startswith("BM_Eval/"):
            if b.get("time_unit") != "ns":
                raise BenchError(f"{path}: {b['run_name']}: time unit {b.get('time_unit')}")
            figures[f"eval_{b['run_name'][len('BM_Eval/'):]}_ns"] = b["cpu_time"]
    return figures


def read_text(path):
    try:
        return path.read_text()
    except FileNotFoundError:
        raise BenchError(f"{path}: missing (was the group run?)") from None


def ring_figures(path):
    """ring_latency.py's first Markdown table: per model, preview and final p95 (seconds). Columns
    are found by their headers, so a column added to the table does not shift the ones read; the
    tables after it (per tab) are not read."""
    lines = []
    for line in read_text(path).splitlines():
        if line.startswith("|"):
            lines.append(line)
        elif lines:
            break
    if len(lines) < 3:
        raise BenchError(f"{path}: no table")
    header = [c.strip() for c in lines[0].strip("|").split("|")]
    p95 = [i for i, h in enumerate(header) if h.startswith("p95")]
    if len(p95) != 2 or header[0] != "model":
        raise BenchError(f"{path}:1: expected a model column and two p95 columns: {lines[0]}")
    figures = {}
    for n, line in enumerate(lines[2:], start=3):
        cells = [c.strip() for c in line.strip("|").split("|")]
        for column, i in zip(("preview", "final"), p95):
            if cells[i] != "-":
                try:
                    figures[f"{cells[0]}_{column}_p95"] = float(cells[i])
                except (ValueError, IndexError):
                    raise BenchError(f"{path}: table row {n}: not a number: {line}") from None
    return figures


def group_figures(group, out):
    if group == "closures":
        return closure_figures(out / "closures.benchmark.json")
    if group in ("ring", "ring8"):
        figures = ring_figures(out / f"{group}.txt")
        figures.update(read_json(out / f"{group}.memory.json"))
        return figures
    document, path = read_json(out / f"{group}.json"), out / f"{group}.json"
    figures = document.get("figures", document) if isinstance(document, dict) else None
    if not isinstance(figures, dict):
        raise BenchError(f"{path}: expected a JSON object of figures")
    return figures


# ---------------------------------------------------------------------------------------------
# The table in bench/RESULTS.md.


def split_row(line):
    """A table row's cells, unescaped (a command may hold a `|`, written `\\|`)."""
    cells = re.split(r"(?<!\\)\|", line.strip())
    return [c.strip().replace("\\|", "|") for c in cells[1:-1]]


def read_table(path):
    """(text before the table, rows by id, text after it); every row must be one of TARGETS."""
    text = path.read_text()
    if text.count(BEGIN) != 1 or text.count(END) != 1:
        raise BenchError(f"{path}: expected one '{BEGIN}' and one '{END}' line")
    head, rest = text.split(BEGIN + "\n", 1)
    body, tail = rest.split(END, 1)
    first = head.count("\n") + 2
    rows = {}
    for n, line in enumerate(body.splitlines(), start=first):
        if not line.startswith("|"):
            continue
        cells = split_row(line)
        if len(cells) != len(HEADER):
            raise BenchError(f"{path}:{n}: {len(cells)} cells, expected {len(HEADER)}: {line}")
        if cells == HEADER or set(cells[0]) <= set("-: "):
            continue
        if cells[0] not in BY_ID:
            raise BenchError(f"{path}:{n}: '{cells[0]}' is not a target of bench/results.py")
        rows[cells[0]] = cells
    return head, rows, tail


def write_table(path, head, rows, tail):
    lines = ["| " + " | ".join(HEADER) + " |", "|" + "---|" * len(HEADER)]
    for t in TARGETS:
        row = rows.get(t.id) or [t.id, t.text, t.pending, "-", "-", "-", "-", "-"]
        row[1] = t.text  # the script's wording of the target is the one shown
        lines.append("| " + " | ".join(c.replace("|", "\\|") for c in row) + " |")
    text = head + BEGIN + "\n" + "\n".join(lines) + "\n" + END + tail
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    tmp.replace(path)


def chosen_targets(names, slow):
    if not names:
        return [t for t in TARGETS if slow or t.group not in SLOW]
    chosen = []
    for name in names:
        found = [t for t in TARGETS if t.group == name or t.id == name]
        if not found:
            raise BenchError(f"'{name}' is neither a group ({', '.join(GROUPS)}) nor a target id")
        chosen += [t for t in found if t not in chosen]
    return chosen


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("names", nargs="*", metavar="NAME", help="groups or target ids")
    parser.add_argument("--build", default=os.environ.get("BRDFNAV_BUILD_DIR", ROOT / "build"))
    parser.add_argument("--db",
                        default=os.environ.get("BRDFNAV_BENCH_DB", str(ROOT / "out/db-default")),
                        help="the default-profile database the navigator's groups read "
                        "(default: the one ./run demo builds)")
    parser.add_argument("--results", default=ROOT / "bench/RESULTS.md", type=Path)
    parser.add_argument("--slow", action="store_true", help="also the slow groups: " +
                        ", ".join(sorted(SLOW)))
    parser.add_argument("--filter", help="closures only: a Google Benchmark filter")
    parser.add_argument("--from", dest="saved", type=Path,
                        help="read the outputs saved in this directory; run nothing")
    args = parser.parse_args(argv)
    try:
        targets = chosen_targets(args.names, args.slow)
        groups = list(dict.fromkeys(t.group for t in targets))
        head, rows, tail = read_table(args.results)  # a malformed table fails before any run
        out = args.saved or Path(args.build) / "bench-results"
        if not args.saved:
            out.mkdir(parents=True, exist_ok=True)
            for group in groups:
                for old in (f"{group}.stamp.json", f"{group}.skipped"):
                    (out / old).unlink(missing_ok=True)
                before = stamp(args)
                command = run_group(group, args, out)
                if command is None:
                    (out / f"{group}.skipped").write_text("cannot run here yet\n")
                    print(f"bench/results.py: {group}: skipped, cannot run here yet",
                          file=sys.stderr)
                    continue
                after = os.getloadavg()[0]
                write_json(out / f"{group}.stamp.json",
                           {**before, "machine": f"{before['machine']} -> {after:.1f}",
                            "command": command})
        updated = 0
        for t in targets:
            if (out / f"{t.group}.skipped").exists():
                continue  # its row stays as it was
            s = read_json(out / f"{t.group}.stamp.json")
            try:
                figures = group_figures(t.group, out)
                if t.group == "closures" and f"eval_{t.id.split('.')[-1]}_ns" not in figures:
                    if args.filter:
                        continue  # the filter left this benchmark out: its row stays
                figure, met = t.check(figures)
            except BenchError as e:
                raise BenchError(f"{out / t.group}.*: {t.id}: {e}") from None
            updated += 1
            rows[t.id] = [t.id, t.text, figure, "met" if met else "**not met**", s["date"],
                          s["commit"], s["machine"], f"`{s['command']}`"]
        write_table(args.results, head, rows, tail)
        print(f"bench/results.py: {updated} rows of {args.results} rewritten", file=sys.stderr)
    except BenchError as e:
        print(f"bench/results.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
