// FX functions become GLSL functions, and GLSL has no recursion: refuse it here with the cycle.
#include <algorithm>
#include <map>
#include <tuple>

#include "analyzer.hpp"

namespace pfx::fx {

void Analyzer::check_recursion() {
  auto definition = [this](const FunctionDecl* f) {
    auto it = definition_of_.find(f);
    return it == definition_of_.end() ? f : it->second;
  };
  std::map<const FunctionDecl*, std::vector<std::pair<const FunctionDecl*, SourceLocation>>> graph;
  for (const auto& [caller, callees] : calls_)
    for (const auto& [callee, where] : callees) graph[definition(caller)].push_back({definition(callee), where});
  // Iterative depth-first search (deep call chains must not deepen the compiler's stack).
  enum class Mark { kNew, kOnPath, kDone };
  std::map<const FunctionDecl*, Mark> marks;
  // Start from callers in source order, so the cycle reported does not depend on addresses.
  std::vector<const FunctionDecl*> callers;
  for (const auto& entry : graph) callers.push_back(entry.first);
  std::sort(callers.begin(), callers.end(), [](const FunctionDecl* a, const FunctionDecl* b) {
    return std::tie(a->location.file, a->location.line, a->location.column) <
           std::tie(b->location.file, b->location.line, b->location.column);
  });
  for (const FunctionDecl* first : callers) {
    if (marks[first] != Mark::kNew) continue;
    const std::pair<const FunctionDecl* const, int> start{first, 0};
    struct Step {
      const FunctionDecl* function;
      std::size_t next;
    };
    std::vector<Step> path{{start.first, 0}};
    marks[start.first] = Mark::kOnPath;
    while (!path.empty()) {
      Step& step = path.back();
      const auto& edges = graph[step.function];
      if (step.next >= edges.size()) {
        marks[step.function] = Mark::kDone;
        path.pop_back();
        continue;
      }
      const auto& [callee, where] = edges[step.next++];
      Mark& mark = marks[callee];
      if (mark == Mark::kNew) {
        mark = Mark::kOnPath;
        path.push_back({callee, 0});
      } else if (mark == Mark::kOnPath) {
        std::string cycle;
        bool in_cycle = false;
        for (const Step& s : path) {
          in_cycle = in_cycle || s.function == callee;
          if (in_cycle) cycle += s.function->name + " -> ";
        }
        diagnostics_.error(where, "recursive call to '" + callee->name + "' (" + cycle + callee->name +
                                      "): FX functions cannot recurse");
      }
    }
  }
}

}  // namespace pfx::fx
