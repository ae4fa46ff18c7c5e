// The figures a `brdfnav bench` command writes with --json FILE, for bench/results.py, which
// compares them with their targets and rewrites the table at the top of bench/RESULTS.md. The
// Markdown tables the commands print stay for people; the runner reads only these files, so a
// change to a printed table cannot silently change a figure.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace brdfnav::cli {

// Named figures in the order they were added, written as one flat JSON object
// {"bench": "<command>", "figures": {"<name>": <number>, ...}}.
class BenchFigures {
 public:
  explicit BenchFigures(std::string bench) : bench_(std::move(bench)) {}
  void add(const std::string& name, double value) { figures_.emplace_back(name, value); }
  // Writes the object to `path` through a temporary file renamed into place (nothing when `path`
  // is empty); throws std::runtime_error naming the file when it cannot be written, and for a
  // figure that is not finite (JSON has no NaN).
  void write(const std::string& path) const;

 private:
  std::string bench_;
  std::vector<std::pair<std::string, double>> figures_;
};

}  // namespace brdfnav::cli
