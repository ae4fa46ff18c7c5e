#!/usr/bin/env python3
"""From a click to every final image of the new ring, as the page asks for them, against a running
`brdfnav serve`:

    brdfnav serve --db DB --port 8080 &
    bench/ring_latency.py --url http://127.0.0.1:8080 [--exact] [--radius 0.03] \\
        [--clients N [--rings R] [--server-pid PID]] [--fractions F,...] [--json]

For each model of the database, three materials (each parameter at 30%, 50% and 70% of its grid,
or at --fractions; grey rho_d 0.2 and rho_s 0.3) and each of the lobe, diffuse, specular and
models tabs, as the page does: under --exact, the embedding's ring (POST /api/neighbors) and the
previews of the centre and its offers, 8 at a time as a browser fetches them (the "preview" time);
then the query with "exact": true and the exact ring's thumbnails (the "final" time). Without
--exact, the embedding's ring and its exact thumbnails. Every request names its ring ({client, id})
as the page does.
Prints median, p95 and max seconds per model. Start a fresh server for each run: its cache of
renders would otherwise answer.

With --clients N, N pages click through rings at once, each with its own client id and its own
materials (rho_d 0.2 + 0.05 per page, so that no page is answered from another's renders), each
starting at another place in the list above and taking R rings of it (--rings, default all).
Then also the p95 over every page's rings, and the server's resident memory (VmRSS of
/proc/PID/status, sampled twice a second: PID from --server-pid, else the `brdfnav serve`
listening on the URL's port) at the start, its peak, half-way, at the end and its trend, with
its anonymous and file-mapped parts; and which lobes were rendered rather than blended, per ring's
model and tab. --json adds a last line of JSON with these figures.
"""

import argparse
import concurrent.futures
import json
import os
import statistics
import sys
import threading
import time
import urllib.error
import urllib.parse
import urllib.request

TABS = ("lobe", "diffuse", "specular", "models")
FRACTIONS = (0.3, 0.5, 0.7)


def p95(seconds):
    seconds = sorted(seconds)
    return seconds[min(len(seconds) - 1, round(0.95 * (len(seconds) - 1)))]


def quantiles(seconds):
    if not seconds:
        return "- | - | -"
    return f"{statistics.median(seconds):.3f} | {p95(seconds):.3f} | {max(seconds):.3f}"


def server_pid(url):
    """The pid of the `brdfnav serve` whose command line names the URL's port."""
    port = str(urllib.parse.urlparse(url).port)
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                words = f.read().decode(errors="replace").split("\0")
        except OSError:
            continue
        if "serve" not in words or not any(w.endswith("brdfnav") for w in words[:1]):
            continue
        if any(w == f"--port={port}" for w in words) or any(
                a == "--port" and b == port for a, b in zip(words, words[1:])):
            found.append(int(entry))
    if len(found) != 1:
        sys.exit(f"ring_latency.py: --server-pid: {len(found)} `brdfnav serve --port {port}` "
                 "processes found; name the server's pid")
    return found[0]


class RssSampler(threading.Thread):
    """A process's resident memory in MiB (VmRSS, and its parts RssAnon: heap and stacks, and
    RssFile: mapped files such as the database's embeddings), every `period` seconds until
    stop()."""

    FIELDS = ("VmRSS", "RssAnon", "RssFile")

    def __init__(self, pid, period=0.5):
        super().__init__(daemon=True)
        self.path, self.period = f"/proc/{pid}/status", period
        self.samples = []  # (seconds since start, {field: MiB})
        self.done = threading.Event()
        self.start_time = time.monotonic()
        self.sample()

    def sample(self):
        try:
            with open(self.path) as f:
                found = {line.split(":")[0]: int(line.split()[1]) / 1024 for line in f
                         if line.split(":")[0] in self.FIELDS}
        except OSError as e:
            sys.exit(f"ring_latency.py: {self.path}: {e.strerror}")
        self.samples.append((time.monotonic() - self.start_time, found))

    def run(self):
        while not self.done.wait(self.period):
            self.sample()

    def stop(self):
        self.done.set()
        self.join()
        self.sample()

    @staticmethod
    def slope(samples):
        """MiB per minute of a least-squares line through (seconds, MiB) samples."""
        if len(samples) < 2:
            return 0.0
        mean_t = statistics.fmean(t for t, _ in samples)
        mean_m = statistics.fmean(m for _, m in samples)
        spread = sum((t - mean_t) ** 2 for t, _ in samples)
        return 60 * sum((t - mean_t) * (m - mean_m) for t, m in samples) / spread if spread else 0

    def figures(self):
        """Start, peak and end MiB, and the trend over the run and over its second half (a cache
        filling up grows at first; a leak keeps growing), of VmRSS; the start, end and
        second-half trend of its parts."""
        out = {}
        for field, key in (("VmRSS", "rss"), ("RssAnon", "anon"), ("RssFile", "file")):
            series = [(t, f[field]) for t, f in self.samples if field in f]
            if not series:
                continue
            mibs = [m for _, m in series]
            half = series[len(series) // 2:]
            out[f"{key}_start_mib"], out[f"{key}_end_mib"] = round(mibs[0], 1), round(mibs[-1], 1)
            out[f"{key}_trend_last_half_mib_per_min"] = round(self.slope(half), 2)
            if key == "rss":
                out["rss_peak_mib"] = round(max(mibs), 1)
                out["rss_mid_mib"] = round(half[0][1], 1)  # where the second half starts
                out["rss_trend_mib_per_min"] = round(self.slope(series), 2)
        return out


class Page:
    """One simulated page: its client id and its rings' numbers."""

    def __init__(self, args, client):
        self.args, self.client, self.ring = args, client, 0

    def post(self, path, body, header=None):
        """The answer's body, or with `header` (body, that header's value)."""
        request = urllib.request.Request(self.args.url + path, data=json.dumps(body).encode(),
                                         headers={"Content-Type": "application/json"})
        with urllib.request.urlopen(request) as answer:
            data = answer.read()
            return (data, answer.headers.get(header)) if header else data

    def thumbnails(self, materials, preview, ring):
        """The materials whose thumbnails were renders (X-Brdfnav-Image), not blends."""
        def one(m):
            body = {"material": m, "preview": preview, "ring": ring}
            return self.post("/api/thumbnail", body, "X-Brdfnav-Image")[1] == "render"

        with concurrent.futures.ThreadPoolExecutor(8) as pool:
            return [m for m, rendered in zip(materials, pool.map(one, materials)) if rendered]

    def click(self, current, tab):
        """A new ring around `current`: (preview seconds or None, final seconds, the materials
        of its final images that were renders)."""
        self.ring += 1
        ring = {"client": self.client, "id": self.ring}
        started = time.monotonic()
        query = {"material": current, "radius": self.args.radius, "tab": tab, "ring": ring}
        preview = None
        if self.args.exact:
            quick = json.loads(self.post("/api/neighbors", query))["neighbors"]
            self.thumbnails([current] + [n["material"] for n in quick], True, ring)
            preview = time.monotonic() - started
        placed = self.post("/api/neighbors", {**query, "exact": self.args.exact})
        offers = json.loads(placed)["neighbors"]
        renders = self.thumbnails([current] + [n["material"] for n in offers], False, ring)
        return preview, time.monotonic() - started, renders


def fractions(text):
    """--fractions: comma-separated numbers in [0, 1]."""
    try:
        values = tuple(float(x) for x in text.split(","))
    except ValueError:
        values = ()
    if not values or not all(0 <= v <= 1 for v in values):
        raise argparse.ArgumentTypeError(f"expected numbers in [0, 1] separated by commas: {text!r}")
    return values


def material(model, fraction, rho_d=0.2):
    params = {}
    for p in model["params"]:
        grid = p["grid"]
        params[p["name"]] = grid[min(len(grid) - 1, int(fraction * (len(grid) - 1)))]
    return {"model": model["name"], "params": params, "rho_d": [rho_d] * 3, "rho_s": [0.3] * 3,
            "colorspace": "lin_rec709"}


def run_page(page, models, index, results, lock):
    """Page `index` clicks through the rings of `models`; appends (model, tab, preview, final,
    renders) to `results`."""
    rho_d = 0.2 + 0.05 * index
    rings = [(model, fraction, tab) for model in models for fraction in page.args.fractions
             for tab in TABS]
    start = index * len(rings) // page.args.clients
    order = rings[start:] + rings[:start]
    for model, fraction, tab in order[:page.args.rings or len(order)]:
        preview, final, renders = page.click(material(model, fraction, rho_d), tab)
        with lock:
            results.append((model["name"], tab, preview, final, renders))


def lobe_name(m):
    """A rendered material's lobe, as a name: its colours vary from page to page, its lobe is
    what the database's cells vouch for or not."""
    return m["model"] + " " + " ".join(f"{k}={v:.6g}" for k, v in sorted(m["params"].items()))


def print_renders(results):
    """Which lobes were rendered, in which model's tab, and how often: where the database does
    not vouch for its blends, which is where a ring waits."""
    seen = {}
    for model, tab, _, _, rendered in results:
        for m in rendered:
            key = (model, tab, lobe_name(m))
            seen[key] = seen.get(key, 0) + 1
    if not seen:
        print("Every final image was a blend.\n")
        return
    print("| ring's model | tab | rendered lobe | images |\n|---|---|---|---:|")
    for (model, tab, lobe), count in sorted(seen.items()):
        print(f"| {model} | {tab} | {lobe} | {count} |")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--url", required=True, help="where brdfnav serve listens")
    parser.add_argument("--radius", type=float, default=0.03)
    parser.add_argument("--exact", action="store_true", help="offers placed by rendering")
    parser.add_argument("--clients", type=int, default=1, help="pages clicking at once")
    parser.add_argument("--rings", type=int, default=0, help="rings per page (0: all)")
    parser.add_argument("--server-pid", type=int, help="the server's pid, for its memory")
    parser.add_argument("--fractions", type=fractions, default=FRACTIONS,
                        help="where along each parameter's grid the materials are, as fractions "
                             "(default: 0.3,0.5,0.7)")
    parser.add_argument("--json", action="store_true", help="a last line of JSON")
    args = parser.parse_args()
    if args.clients < 1 or args.rings < 0:
        sys.exit("ring_latency.py: --clients: at least 1; --rings: at least 0")

    with urllib.request.urlopen(args.url + "/api/info") as answer:
        info = json.loads(answer.read())
    many = args.clients > 1
    sampler = None
    if many or args.server_pid or args.json:
        sampler = RssSampler(args.server_pid or server_pid(args.url))
        sampler.start()
    load_start = [round(x, 2) for x in os.getloadavg()]

    print(f"{args.url}: radius {args.radius}, {'exact' if args.exact else 'embedded'} steps" +
          (f", {args.clients} pages at once" if many else ""))
    print("| model | rings | preview median s | p95 s | max s | final median s | p95 s | max s |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|")
    results, lock = [], threading.Lock()

    def table_row(name):
        previews = [p for m, _, p, _, _ in results if m == name and p is not None]
        finals = [f for m, _, _, f, _ in results if m == name]
        print(f"| {name} | {len(finals)} | {quantiles(previews)} | {quantiles(finals)} |",
              flush=True)

    if many:
        threads = [threading.Thread(target=run_page, args=(Page(args, f"bench-{os.getpid()}-{i}"),
                                                           info["models"], i, results, lock))
                   for i in range(args.clients)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for model in info["models"]:
            table_row(model["name"])
    else:  # one page, each model's row as soon as it is measured
        page = Page(args, f"bench-{os.getpid()}-0")
        for model in info["models"]:
            run_page(page, [model], 0, results, lock)
            table_row(model["name"])

    # Per model and tab: the final p95, and how many rings needed no render (every final image a
    # blend the database vouches for, every exact step measured on blends).
    print("\n| model | " + " | ".join(f"{t} final p95 s (rings without a render)" for t in TABS) +
          " |\n|---|" + "---:|" * len(TABS))
    for model in info["models"]:
        cells = []
        for tab in TABS:
            ring = [(f, r) for m, t, _, f, r in results if m == model["name"] and t == tab]
            cells.append(f"{p95([f for f, _ in ring]):.3f} ({sum(not r for _, r in ring)}/"
                         f"{len(ring)})" if ring else "-")
        print(f"| {model['name']} | " + " | ".join(cells) + " |")
    print()
    print_renders(results)
    summary = {"clients": args.clients, "rings": len(results),
               "rings_without_render": sum(1 for *_, r in results if not r),
               "final_p95_s": round(p95([f for _, _, _, f, _ in results]), 3)}
    previews = [p for _, _, p, _, _ in results if p is not None]
    if previews:
        summary["preview_p95_s"] = round(p95(previews), 3)
    if sampler:
        sampler.stop()
        summary.update(sampler.figures())
    load_end = [round(x, 2) for x in os.getloadavg()]
    summary["load_average_start"], summary["load_average_end"] = load_start, load_end
    if many:
        print(f"all pages: {summary['rings']} rings, final p95 {summary['final_p95_s']:.3f} s" +
              (f", preview p95 {summary['preview_p95_s']:.3f} s" if previews else ""))
    if many or args.server_pid:
        print(f"server RSS: start {summary['rss_start_mib']} MiB, peak {summary['rss_peak_mib']} "
              f"MiB, half-way {summary['rss_mid_mib']} MiB, end {summary['rss_end_mib']} MiB, trend {summary['rss_trend_mib_per_min']} "
              f"MiB/min ({summary['rss_trend_last_half_mib_per_min']} over the second half); "
              f"of it anonymous {summary.get('anon_start_mib')} -> {summary.get('anon_end_mib')} "
              f"MiB ({summary.get('anon_trend_last_half_mib_per_min')} MiB/min over the second "
              f"half), mapped files {summary.get('file_start_mib')} -> "
              f"{summary.get('file_end_mib')} MiB; "
              f"load average (1, 5, 15 min) at start {load_start}, at end {load_end}")
    if args.json:
        print(json.dumps(summary))


if __name__ == "__main__":
    main()
