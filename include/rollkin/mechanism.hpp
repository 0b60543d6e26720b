// The mechanism description (the "model"): links, their contours, pairs, the variable layout, the drivers
// and the independent loops found from the link/pair graph. It holds no solve state; see solve/*.hpp.
#pragma once

#include "rollkin/pair/pair.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin {

struct Link {
  std::string name;
};

/// One step of a loop: a pair traversed from its link A to its link B (forward) or backwards.
struct LoopEdge {
  int pair;
  bool forward;
};

/// Where a link sits in the spanning tree rooted at the ground: reached from `parent` through `edge`.
struct TreeEdge {
  int parent = -1;
  LoopEdge edge{-1, true};
};

struct Variable {
  std::string name;   // "<pair>.<var>"
  ParamKind kind;
  int pair;
};

template <class S> class Mechanism {
 public:
  using Scalar = S;

  std::vector<Link> links;          // links[ground] is the fixed frame
  int ground = 0;
  std::vector<Contour<S>> contours;
  std::vector<Pair<S>> pairs;
  std::vector<int> drivers;         // indices into q of the input variables

  // Derived by finalize():
  std::vector<Variable> variables;
  std::vector<std::vector<LoopEdge>> loops;
  std::vector<TreeEdge> tree;       // per link
  std::vector<int> tree_order;      // links in breadth-first order from the ground (parents first)
  std::vector<int> unknowns;        // indices into q that are not drivers
  std::vector<int> rolling_pairs;   // pairs with an arc-length row
  S length_scale = S(1);            // characteristic size, for scaling lengths in norms
  S representation_error = S(0);    // largest Contour::representation_error (0 for exact contours)

  int variable_count() const { return static_cast<int>(variables.size()); }
  int equation_count() const { return 3 * static_cast<int>(loops.size()) + static_cast<int>(rolling_pairs.size()); }

  int find_link(const std::string& name) const { return find_by_name(links, name); }
  int find_pair(const std::string& name) const { return find_by_name(pairs, name); }
  int find_contour(const std::string& name) const { return find_by_name(contours, name); }
  int find_variable(const std::string& name) const { return find_by_name(variables, name); }

  /// Numbers the variables, finds the spanning tree and the independent loops (one per chord of the
  /// tree, from the chord's endpoints up to their lowest common ancestor), and the length scale.
  /// Throws std::invalid_argument if a link cannot be reached from the ground.
  void finalize();

  /// Scale of a variable in norms: angles and unitless parameters 1, lengths length_scale.
  S variable_scale(int i) const { return variables[i].kind == ParamKind::Length ? length_scale : S(1); }

  template <class T> Mechanism<T> cast() const {
    Mechanism<T> m;
    m.links = links;
    m.ground = ground;
    for (const auto& c : contours) m.contours.push_back(c.template cast<T>());
    for (const auto& p : pairs) m.pairs.push_back(p.template cast<T>());
    m.drivers = drivers;
    m.variables = variables;
    m.loops = loops;
    m.tree = tree;
    m.tree_order = tree_order;
    m.unknowns = unknowns;
    m.rolling_pairs = rolling_pairs;
    m.length_scale = scalar_cast<T>(length_scale);
    m.representation_error = scalar_cast<T>(representation_error);
    return m;
  }

 private:
  template <class V> static int find_by_name(const V& v, const std::string& name) {
    for (std::size_t i = 0; i < v.size(); ++i)
      if (name_of(v[i]) == name) return static_cast<int>(i);
    return -1;
  }
  template <class X> static const std::string& name_of(const X& x) { return x.name; }
  static const std::string& name_of(const Contour<S>& c) { return c.name(); }

  void number_variables();
  void build_tree_and_loops();
  void estimate_length_scale();
};

template <class S> void Mechanism<S>::finalize() {
  number_variables();
  build_tree_and_loops();
  estimate_length_scale();
  representation_error = S(0);
  for (const auto& c : contours) {
    using std::max;
    representation_error = max(representation_error, c.representation_error());
  }
}

template <class S> void Mechanism<S>::number_variables() {
  variables.clear();
  rolling_pairs.clear();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    Pair<S>& p = pairs[k];
    p.first_variable = static_cast<int>(variables.size());
    const PairTraits& t = p.traits();
    for (int j = 0; j < p.variable_count(); ++j) {
      const ParamKind kind = t.has_contours ? contours[j == 0 ? p.contour_a : p.contour_b].parameter_kind()
                                            : t.joint_variable_kind();
      variables.push_back(Variable{p.name + "." + p.variables[j], kind, static_cast<int>(k)});
    }
    if (t.constrains_sliding) rolling_pairs.push_back(static_cast<int>(k));
    p.frame_a_identity = p.frame_a.is_identity();
    p.frame_b_identity = p.frame_b.is_identity();
  }
  std::vector<bool> driven(variables.size(), false);
  for (int d : drivers)
    if (d >= 0 && d < variable_count()) driven[static_cast<std::size_t>(d)] = true;
  unknowns.clear();
  for (int i = 0; i < variable_count(); ++i)
    if (!driven[static_cast<std::size_t>(i)]) unknowns.push_back(i);
}

template <class S> void Mechanism<S>::build_tree_and_loops() {
  const int n = static_cast<int>(links.size());
  tree.assign(n, TreeEdge{});
  std::vector<int> depth(n, -1);
  std::vector<bool> in_tree(pairs.size(), false);
  // The pairs at each link, in pair order: the search below visits them as a scan of every pair would, in
  // time linear in the links and pairs (a scan per link was quadratic: 10^4 four-bar loops took 4 s).
  std::vector<std::vector<int>> pairs_at(static_cast<std::size_t>(n));
  auto on_link = [n](int link) { return link >= 0 && link < n; };
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const int a = pairs[k].link_a, b = pairs[k].link_b;
    if (on_link(a)) pairs_at[static_cast<std::size_t>(a)].push_back(static_cast<int>(k));
    if (on_link(b) && b != a) pairs_at[static_cast<std::size_t>(b)].push_back(static_cast<int>(k));
  }
  std::vector<int> queue{ground};
  depth[ground] = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {  // breadth-first: short loops
    const int at = queue[head];
    for (const int pair : pairs_at[static_cast<std::size_t>(at)]) {
      const std::size_t k = static_cast<std::size_t>(pair);
      const Pair<S>& p = pairs[k];
      const bool from_a = p.link_a == at, from_b = p.link_b == at;
      if (!from_a && !from_b) continue;
      const int other = from_a ? p.link_b : p.link_a;
      if (depth[other] >= 0) continue;
      depth[other] = depth[at] + 1;
      tree[other] = TreeEdge{at, LoopEdge{static_cast<int>(k), from_a}};
      in_tree[k] = true;
      queue.push_back(other);
    }
  }
  tree_order = queue;
  for (int i = 0; i < n; ++i)
    if (depth[i] < 0) throw std::invalid_argument("link '" + links[i].name + "' is not connected to the ground");

  loops.clear();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (in_tree[k]) continue;
    // Loop: LCA -> ... -> A, chord A -> B, B -> ... -> LCA.
    int a = pairs[k].link_a, b = pairs[k].link_b;
    std::vector<LoopEdge> down_to_a, up_from_b;
    while (a != b) {
      if (depth[a] >= depth[b]) {
        down_to_a.push_back(tree[a].edge);
        a = tree[a].parent;
      } else {
        up_from_b.push_back(LoopEdge{tree[b].edge.pair, !tree[b].edge.forward});
        b = tree[b].parent;
      }
    }
    std::vector<LoopEdge> loop(down_to_a.rbegin(), down_to_a.rend());
    loop.push_back(LoopEdge{static_cast<int>(k), true});
    loop.insert(loop.end(), up_from_b.begin(), up_from_b.end());
    loops.push_back(std::move(loop));
  }
}

template <class S> void Mechanism<S>::estimate_length_scale() {
  using std::max;
  S scale(0);
  for (const auto& p : pairs) {
    scale = max(scale, p.frame_a.translation().norm());
    scale = max(scale, p.frame_b.translation().norm());
  }
  for (const auto& c : contours) {
    scale = max(scale, c.placement().translation().norm());
    const Domain<S> d = c.domain();
    if (!d.closed) {
      scale = max(scale, c.jet(d.lo, 0).p.norm());
      scale = max(scale, c.jet(d.hi, 0).p.norm());
    } else {
      scale = max(scale, c.jet(d.lo + d.period() / S(4), 0).p.norm());
      scale = max(scale, c.jet(d.lo, 0).p.norm());
    }
  }
  length_scale = scale > S(0) ? scale : S(1);
}

}  // namespace rollkin
