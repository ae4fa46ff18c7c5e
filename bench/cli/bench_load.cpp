// `brdfnav bench load`: many threads querying one open database (docs/RELIABILITY.md, Load). Every
// answer is compared with the one a serial pass gave for the same query, and the resident memory is
// read at the start, the middle and the end, which should not grow once every thread has its
// working memory.
#include "bench_load.h"
#include "bench_navigator.h"

#include <brdfnav/navigator/navigator.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace brdfnav::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Query {
  Material material;
  double radius;
  Tab tab;
};

// Random materials of every model, each in every tab at a small and a large radius.
std::vector<Query> query_pool(const Database& db) {
  std::vector<Query> pool;
  for (const Material& m : random_materials(db, 20))
    for (Tab tab : kTabs)
      for (double radius : {0.01, 0.05}) pool.push_back({m, radius, tab});
  return pool;
}

bool same(const Neighbor& a, const Neighbor& b) {
  const Material &x = a.material, &y = b.material;
  return a.tab == b.tab && a.label == b.label && a.distance == b.distance &&
         a.at_boundary == b.at_boundary && a.clamped == b.clamped && x.model == y.model &&
         x.params == y.params && (x.rho_d == y.rho_d).all() && (x.rho_s == y.rho_s).all() &&
         x.colorspace == y.colorspace;
}

bool same(const std::vector<Neighbor>& a, const std::vector<Neighbor>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(a[i], b[i])) return false;
  return true;
}

std::vector<Neighbor> answer(const Navigator& navigator, const Query& q) {
  return navigator.neighbors(q.material, q.radius, q.tab);
}

// The resident memory when half the queries are done, read by the calling thread while the
// workers run.
double middle_rss(const std::atomic<long>& done, long total) {
  while (done.load() < total / 2) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return resident_mib();
}

}  // namespace

void run_load_bench(const LoadBenchOptions& o) {
  const Navigator navigator = Navigator::open(o.db);
  const std::vector<Query> pool = query_pool(navigator.database());
  std::vector<std::vector<Neighbor>> serial;
  const auto serial_start = Clock::now();
  for (const Query& q : pool) serial.push_back(answer(navigator, q));
  const double serial_s = seconds_since(serial_start);
  std::printf(
      "database %s (profile %s): %zu distinct queries, serial pass %.2f s (%.0f queries/s)\n",
      o.db.c_str(), navigator.database().manifest().profile.c_str(), pool.size(), serial_s,
      double(pool.size()) / serial_s);

  const double start_rss = resident_mib();
  const long total = long(o.threads) * o.queries;
  std::atomic<long> done{0}, mismatches{0};
  const auto start = Clock::now();
  double mid_rss = 0;
  {
    std::vector<std::jthread> workers;
    for (int t = 0; t < o.threads; ++t)
      workers.emplace_back([&, t] {
        // Each thread walks the pool from its own start, so that different queries overlap.
        for (long i = 0; i < o.queries; ++i, ++done) {
          const std::size_t k = std::size_t(i + long(t) * 131) % pool.size();
          if (!same(answer(navigator, pool[k]), serial[k])) ++mismatches;
        }
      });
    mid_rss = middle_rss(done, total);
  }
  const double seconds = seconds_since(start);
  std::printf("%d threads x %d queries: %.1f s, %.0f queries/s, %ld mismatches vs serial\n",
              o.threads, o.queries, seconds, double(total) / seconds, mismatches.load());
  std::printf("resident memory: start %.1f MiB, middle %.1f MiB, end %.1f MiB\n", start_rss,
              mid_rss, resident_mib());
  if (mismatches > 0)
    throw std::runtime_error("bench load: " + std::to_string(mismatches.load()) +
                             " concurrent answers differ from the serial ones");
}

}  // namespace brdfnav::cli
