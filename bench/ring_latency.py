#!/usr/bin/env python3
"""From a click to every final image of the new ring, as the page asks for them, against a running
`brdfnav serve`:

    brdfnav serve --db DB --port 8080 &
    bench/ring_latency.py --url http://127.0.0.1:8080 [--exact] [--radius 0.03]

For each model of the database, three materials (each parameter at 30%, 50% and 70% of its grid,
grey rho_d 0.2 and rho_s 0.3) and each of the lobe, diffuse, specular and models tabs: one
POST /api/neighbors (with "exact": true under --exact), then the exact thumbnails of the centre
and every offer, 8 at a time as a browser fetches them. Prints median, p95 and max seconds per
model. Start a fresh server for each run: its cache of renders would otherwise answer.
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

    print(f"{args.url}: radius {args.radius}, {'exact' if args.exact else 'embedded'} steps")
    print("| model | rings | median s | p95 s | max s |\n|---|---:|---:|---:|---:|")
    for model in info["models"]:
        seconds = []
        for fraction in (0.3, 0.5, 0.7):
            for tab in ("lobe", "diffuse", "specular", "models"):
                current = material(model, fraction)
                started = time.monotonic()
                query = {"material": current, "radius": args.radius, "tab": tab,
                         "exact": args.exact}
                offers = json.loads(post("/api/neighbors", query))["neighbors"]
                shown = [current] + [n["material"] for n in offers]
                with concurrent.futures.ThreadPoolExecutor(8) as pool:
                    list(pool.map(lambda m: post("/api/thumbnail", {"material": m}), shown))
                seconds.append(time.monotonic() - started)
        seconds.sort()
        p95 = seconds[min(len(seconds) - 1, round(0.95 * (len(seconds) - 1)))]
        print(f"| {model['name']} | {len(seconds)} | {statistics.median(seconds):.2f} | "
              f"{p95:.2f} | {seconds[-1]:.2f} |", flush=True)


if __name__ == "__main__":
    main()
