#include "common/util/memory_budget.hpp"

#include <cmath>
#include <cstdio>

namespace plumbago {

namespace {

double budget_gb = kDefaultMemoryBudgetGb;

constexpr double kGb = 1e9;

std::string gb_text(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, bytes < 0.1 * kGb ? "%.3g" : "%.1f", bytes / kGb);
  return text;
}

}  // namespace

void set_memory_budget_gb(double gb) {
  if (!(gb > 0 && gb <= kMaxMemoryBudgetGb))
    throw std::invalid_argument("--memory-budget-gb: " + std::to_string(gb) + " is out of range (0, " +
                                std::to_string(int64_t(kMaxMemoryBudgetGb)) + "]");
  budget_gb = gb;
}

double memory_budget_gb() { return budget_gb; }

double mesh_bytes(double vertices, double triangles) { return 512 * vertices + 1024 * triangles; }

std::string over_memory_budget(const std::string& what, double bytes) {
  if (bytes <= budget_gb * kGb) return {};
  return what + " would need " + gb_text(bytes) + " GB, over the memory budget of " + gb_text(budget_gb * kGb) +
         " GB (plumbago --memory-budget-gb)";
}

void check_memory_budget(const std::string& what, double bytes) {
  if (std::string why = over_memory_budget(what, bytes); !why.empty()) throw std::length_error(why);
}

}  // namespace plumbago
