// The registry of the algorithms (registry.hpp).
#include "algorithms/registry.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace t2cli::algorithms {
namespace {

template <class T>
struct Store {
  std::vector<T> items;
  bool sorted = false;
};

Store<Problem>& problem_store() {
  static Store<Problem> s;
  return s;
}
Store<Algorithm>& algorithm_store() {
  static Store<Algorithm> s;
  return s;
}
Store<Peer>& peer_store() {
  static Store<Peer> s;
  return s;
}

// Every name of an algorithm or a peer is a word of the command line: it names one thing.
void claim(const std::string& kind, const std::string& name) {
  static std::set<std::string> taken;
  if (name.empty() || !taken.insert(kind + ":" + name).second) {
    std::fprintf(stderr, "t2: the %s '%s' is registered twice (tools/t2/algorithms)\n", kind.c_str(), name.c_str());
    std::abort();
  }
}

}  // namespace

void register_problem(const Problem& p) {
  claim("problem", p.name);
  problem_store().items.push_back(p);
  problem_store().sorted = false;
}

void register_algorithm(const Algorithm& a) {
  claim("implementation", a.name);
  algorithm_store().items.push_back(a);
  algorithm_store().sorted = false;
}

void register_peer(const Peer& p) {
  claim("implementation", p.name);
  peer_store().items.push_back(p);
  peer_store().sorted = false;
}

const std::vector<Problem>& problems() {
  auto& s = problem_store();
  if (!s.sorted) std::sort(s.items.begin(), s.items.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  s.sorted = true;
  return s.items;
}

// By problem; within one, the algorithm named as its problem (what `t2 PROBLEM` runs) first.
const std::vector<Algorithm>& all() {
  auto& s = algorithm_store();
  if (!s.sorted)
    std::sort(s.items.begin(), s.items.end(), [](const Algorithm& a, const Algorithm& b) {
      if (a.problem != b.problem) return a.problem < b.problem;
      if ((a.name == a.problem) != (b.name == b.problem)) return a.name == a.problem;
      return a.name < b.name;
    });
  s.sorted = true;
  return s.items;
}

const std::vector<Peer>& peers() {
  auto& s = peer_store();
  if (!s.sorted) std::sort(s.items.begin(), s.items.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  s.sorted = true;
  return s.items;
}

const Problem* find_problem(const std::string& name) {
  for (const auto& p : problems())
    if (p.name == name) return &p;
  return nullptr;
}

const Algorithm* find(const std::string& name) {
  for (const auto& a : all())
    if (a.name == name) return &a;
  return nullptr;
}

const Peer* find_peer(const std::string& name) {
  for (const auto& p : peers())
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<const Algorithm*> animated() {
  std::vector<const Algorithm*> v;
  for (const auto& a : all())
    if (a.animates()) v.push_back(&a);
  return v;
}

std::vector<const Algorithm*> timed() {
  std::vector<const Algorithm*> v;
  for (const auto& a : all())
    if (a.time) v.push_back(&a);
  return v;
}

std::string words(const std::vector<std::string>& names, const char* last) {
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k)
    s += (k == 0 ? "" : k + 1 == names.size() ? std::string(" ") + last + " " : ", ") + names[k];
  return s;
}

}  // namespace t2cli::algorithms
