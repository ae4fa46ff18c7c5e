#!/usr/bin/env python3
"""From a click to every final image of the new ring, as the page asks for them, against a running
`brdfnav serve`:

    brdfnav serve --db DB --port 8080 &
    bench/ring_latency.py --url http://127.0.0.1:8080 [--exact] [--radius 0.03]

For each model of the database, three materials (each parameter at 30%, 50% and 70% of its grid,
grey rho_d 0.2 and rho_s 0.3) and each of the lobe, diffuse, specular and models tabs, as the page
does: under --exact, the embedding's ring (POST /api/neighbors) and the previews of the centre
and its offers, 8 at a time as a browser fetches them (the "preview" time); then the query with
"exact": true and the exact ring's thumbnails (the "final" time). Without --exact, the embedding's ring and its exact thumbnails. Prints median, p95
and max seconds per model. Start a fresh server for each run: its cache of renders would
otherwise answer.
"""

import argparse
import concurrent.futures
import json
import statistics
import time
import urllib.request


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--url", required=True, help="where brdfnav serve listens")
    parser.add_argument("--radius", type=float, default=0.03)
    parser.add_argument("--exact", action="store_true", help="offers placed by rendering")
    args = parser.parse_args()

    def post(path, body):
        request = urllib.request.Request(args.url + path, data=json.dumps(body).encode(),
                                         headers={"Content-Type": "application/json"})
        with urllib.request.urlopen(request) as answer:
            return answer.read()

    with urllib.request.urlopen(args.url + "/api/info") as answer:
        info = json.loads(answer.read())

    def material(model, fraction):
        params = {}
        for p in model["params"]:
            grid = p["grid"]
            params[p["name"]] = grid[min(len(grid) - 1, int(fraction * (len(grid) - 1)))]
        return {"model": model["name"], "params": params, "rho_d": [0.2] * 3, "rho_s": [0.3] * 3,
                "colorspace": "lin_rec709"}

    def thumbnails(materials, preview):
        with concurrent.futures.ThreadPoolExecutor(8) as pool:
            list(pool.map(lambda m: post("/api/thumbnail", {"material": m, "preview": preview}),
                          materials))

    def quantiles(seconds):
        seconds = sorted(seconds)
        p95 = seconds[min(len(seconds) - 1, round(0.95 * (len(seconds) - 1)))]
        return f"{statistics.median(seconds):.3f} | {p95:.3f} | {seconds[-1]:.3f}"

    print(f"{args.url}: radius {args.radius}, {'exact' if args.exact else 'embedded'} steps")
    print("| model | rings | preview median s | p95 s | max s | final median s | p95 s | max s |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|")
    for model in info["models"]:
        previews, finals = [], []
        for fraction in (0.3, 0.5, 0.7):
            for tab in ("lobe", "diffuse", "specular", "models"):
                current = material(model, fraction)
                started = time.monotonic()
                query = {"material": current, "radius": args.radius, "tab": tab}
                if args.exact:
                    quick = json.loads(post("/api/neighbors", query))["neighbors"]
                    thumbnails([current] + [n["material"] for n in quick], True)
                    previews.append(time.monotonic() - started)
                placed = post("/api/neighbors", {**query, "exact": args.exact})
                offers = json.loads(placed)["neighbors"]
                thumbnails([current] + [n["material"] for n in offers], False)
                finals.append(time.monotonic() - started)
        shown = quantiles(previews) if previews else "- | - | -"
        print(f"| {model['name']} | {len(finals)} | {shown} | {quantiles(finals)} |", flush=True)

if __name__ == "__main__":
    main()
