#include "tierlift/corpus/shard.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include <nlohmann/json.hpp>

namespace tierlift::corpus {

ir::Result<std::map<std::string, uint64_t>> read_costs(const std::string& path) {
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path))
    return ir::fail(path, "io", "cannot read the --shard-costs file (a results.jsonl)");
  std::map<std::string, uint64_t> costs;
  for (std::string line; std::getline(in, line);) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object() || !j.contains("id") || !j.contains("ms") || !j["id"].is_string() ||
        !j["ms"].is_number())
      continue;
    const double ms = j["ms"].get<double>();
    if (!(ms >= 0) || ms > 1e12) continue;
    // The first line of an id is its first attempt (a rerun's line follows it).
    costs.emplace(j["id"].get<std::string>(), static_cast<uint64_t>(std::llround(ms * 1000.0)));
  }
  return costs;
}

namespace {
uint64_t median(const std::map<std::string, uint64_t>& costs) {
  if (costs.empty()) return 1;
  std::vector<uint64_t> v;
  v.reserve(costs.size());
  for (const auto& [id, c] : costs) v.push_back(c);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}
} // namespace

std::vector<Case> balanced_shard(const std::vector<Case>& cases,
                                 const std::map<std::string, uint64_t>& costs, size_t index,
                                 size_t count) {
  const uint64_t unknown = median(costs);
  std::vector<std::pair<uint64_t, size_t>> order; // (cost, position in cases)
  order.reserve(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    auto it = costs.find(cases[i].id);
    order.emplace_back(it == costs.end() ? unknown : it->second, i);
  }
  std::sort(order.begin(), order.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first > b.first;
    return cases[a.second].id < cases[b.second].id; // the input order never decides
  });
  std::vector<uint64_t> total(count, 0);
  std::vector<bool> mine(cases.size(), false);
  for (const auto& [cost, i] : order) {
    const size_t s =
        static_cast<size_t>(std::min_element(total.begin(), total.end()) - total.begin());
    total[s] += cost;
    mine[i] = s == index;
  }
  std::vector<Case> out;
  for (size_t i = 0; i < cases.size(); ++i)
    if (mine[i]) out.push_back(cases[i]);
  return out;
}

std::vector<size_t> costliest_first(const std::vector<Case>& cases, std::vector<size_t> which,
                                    const std::map<std::string, uint64_t>& costs) {
  const uint64_t unknown = median(costs);
  // Costs that name none of these cases (another corpus's run) say nothing about them.
  const bool by_time = std::any_of(which.begin(), which.end(),
                                   [&](size_t i) { return costs.contains(cases[i].id); });
  std::vector<uint64_t> cost(cases.size(), 0);
  for (size_t i : which) {
    const Case& c = cases[i];
    if (by_time) {
      auto it = costs.find(c.id);
      cost[i] = it == costs.end() ? unknown : it->second;
    } else if (c.generated || c.path.empty()) {
      cost[i] = c.text.size();
    } else {
      std::error_code ec;
      const uintmax_t bytes = std::filesystem::file_size(c.path, ec);
      cost[i] = ec ? 0 : static_cast<uint64_t>(bytes);
    }
  }
  std::stable_sort(which.begin(), which.end(),
                   [&](size_t a, size_t b) { return cost[a] > cost[b]; });
  return which;
}

} // namespace tierlift::corpus
