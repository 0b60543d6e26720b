// The DXF entities grouped into chains by their end points and walked end to end (dxf/detail.hpp), and the
// distance from a point to a chain (the "near" selector).
//
// Order-free chaining: every piece (one entity, or a block's entity placed by an INSERT) has two ends; ends
// within the join tolerance of each other are one node (union-find over the ends sorted by x, so that only
// ends within the tolerance in x are compared). Pieces sharing a node are one component. A node where three
// or more piece ends meet is a branch. A component without branches is a path (two nodes with one end) or a
// cycle (every node with two ends), walked from one end.
#include "detail.hpp"
#include "../segment_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace rollkin::io::dxf {
namespace {

V start_of(const Piece& p) { return p.segments.front().points.front(); }
V end_of(const Piece& p) { return p.segments.back().points.back(); }

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

/// Node of every piece end (end 2 k is piece k's start, 2 k + 1 its end): ends within `tol` are one node.
/// The ends are put in square cells of side `tol` (a hash map): two ends within `tol` lie in the same or
/// neighbouring cells, so each end is compared with the ends of nine cells, not with every end of the same x
/// (a MINSERT column, a stack of copies: quadratic). Ends at the same point are joined once, by sorting.
std::vector<std::size_t> end_nodes(const std::vector<Piece>& pieces, double tol) {
  const std::size_t n = 2 * pieces.size();
  std::vector<V> at(n);
  for (std::size_t k = 0; k < pieces.size(); ++k) at[2 * k] = start_of(pieces[k]), at[2 * k + 1] = end_of(pieces[k]);
  UnionFind uf(n);
  std::vector<std::size_t> order(n);  // ends at one point next to each other: joined, then one of them stands for all
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return at[a].x() < at[b].x() || (at[a].x() == at[b].x() && at[a].y() < at[b].y());
  });
  std::vector<std::size_t> distinct;
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && at[order[i]] == at[order[i - 1]]) uf.join(order[i], order[i - 1]);
    else distinct.push_back(order[i]);
  }
  if (tol > 0) {
    using Cell = std::pair<long long, long long>;
    const auto cell_of = [&](const V& p) {
      // coordinates at most 2^62 cells from the origin (a drawing's size over 1e-9 of it: far inside)
      const auto clamp = [](double c) { return static_cast<long long>(std::clamp(std::floor(c), -4.6e18, 4.6e18)); };
      return Cell(clamp(p.x() / tol), clamp(p.y() / tol));
    };
    std::map<Cell, std::vector<std::size_t>> cells;
    for (std::size_t e : distinct) cells[cell_of(at[e])].push_back(e);
    for (std::size_t e : distinct) {
      const Cell c = cell_of(at[e]);
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy) {
          const auto it = cells.find(Cell(c.first + dx, c.second + dy));
          if (it == cells.end()) continue;
          for (std::size_t other : it->second)
            if (other < e && (at[other] - at[e]).norm() <= tol) uf.join(e, other);
        }
    }
  }
  std::vector<std::size_t> node(n);
  for (std::size_t i = 0; i < n; ++i) node[i] = uf.find(i);
  return node;
}

std::string tolerance_text(double tol, double size) {
  return "tolerance " + number(tol) + " = " + number(kDxfJoinTolerance) + " x drawing size " + number(size);
}

}  // namespace

double pieces_size(const std::vector<Piece>& pieces, const std::vector<std::size_t>& which) {
  bool any = false;
  V lo(0, 0), hi(0, 0);
  for (std::size_t k : which)
    for (const Segment& s : pieces[k].segments)
      for (const V& q : s.points) {
        if (!any) lo = hi = q, any = true;
        lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
      }
  return (hi - lo).norm();
}

std::vector<Component> connected_chains(const std::vector<Piece>& pieces, double tol) {
  const std::vector<std::size_t> node = end_nodes(pieces, tol);
  UnionFind uf(pieces.size());
  std::map<std::size_t, std::vector<std::size_t>> ends_at;  // node -> piece ends
  for (std::size_t e = 0; e < node.size(); ++e) ends_at[node[e]].push_back(e);
  for (const auto& [n, ends] : ends_at)
    for (std::size_t e : ends) uf.join(ends.front() / 2, e / 2);
  std::map<std::size_t, std::size_t> index;  // root piece -> component
  std::vector<Component> out;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto [it, fresh] = index.emplace(uf.find(k), out.size());
    if (fresh) out.emplace_back();
    out[it->second].pieces.push_back(k);
  }
  for (const auto& [n, ends] : ends_at) {
    if (ends.size() <= 2) continue;
    Component& c = out[index[uf.find(ends.front() / 2)]];
    if (!c.branch.empty()) continue;
    std::string names;
    for (std::size_t i = 0; i < ends.size(); ++i)
      names += (i ? (i + 1 == ends.size() ? " and " : ", ") : "") + pieces[ends[i] / 2].label + (ends[i] % 2 ? " (end)" : " (start)");
    const V at = ends.front() % 2 ? end_of(pieces[ends.front() / 2]) : start_of(pieces[ends.front() / 2]);
    c.branch = std::to_string(ends.size()) + " entity ends meet at " + point_text(at) + ": " + names;
  }
  return out;
}

Chain walk_chain(const std::string& file, const std::vector<Piece>& pieces, const Component& component, double tol,
                 double size) {
  auto fail = [&](const std::string& message) -> void { throw InputError(file, "", message); };
  if (!component.branch.empty())
    fail("the chain of " + component_entities(pieces, component) + " branches: " + component.branch +
         "; a contour is one chain without branches (select part of it with \"handles\", or move the other entities "
         "to another layer)");
  for (std::size_t k : component.pieces)
    for (const Segment& s : pieces[k].segments) {
      double reach = 0;
      for (const V& q : s.points) reach = std::max(reach, (q - s.points.front()).norm());
      if (!(reach > tol))
        fail(pieces[k].label + " has a piece at " + point_text(s.points.front()) + " no longer than the join tolerance (" +
             tolerance_text(tol, size) + "): nearly repeated vertices or a vanishing arc");
    }
  // ends of the component's pieces, by node
  std::vector<Piece> local;
  for (std::size_t k : component.pieces) local.push_back(pieces[k]);
  const std::vector<std::size_t> node = end_nodes(local, tol);
  std::map<std::size_t, std::vector<std::size_t>> ends_at;
  for (std::size_t e = 0; e < node.size(); ++e) ends_at[node[e]].push_back(e);
  // start: the free end (a node of one end) whose piece comes first in file order, else the first piece's start
  std::size_t first_end = 0;
  bool open = false;
  for (std::size_t e = 0; e < node.size() && !open; ++e)
    if (ends_at[node[e]].size() == 1) first_end = e, open = true;
  Chain c;
  std::vector<bool> used(local.size(), false);
  std::size_t end = first_end;  // the end at which the next piece is entered
  for (std::size_t step = 0; step < local.size(); ++step) {
    const std::size_t k = end / 2;
    const bool reverse = end % 2 == 1;
    used[k] = true;
    const Piece& p = local[k];
    const std::size_t first = c.segments.size();
    if (!reverse) {
      for (const Segment& s : p.segments) c.segments.push_back(s);
    } else {
      for (auto it = p.segments.rbegin(); it != p.segments.rend(); ++it) c.segments.push_back(reversed(*it));
    }
    c.owner.resize(c.segments.size(), component.pieces[k]);
    c.pieces.push_back(component.pieces[k]);
    if (first > 0) c.segments[first].points.front() = c.segments[first - 1].points.back();  // snap the joint
    const std::size_t leave = reverse ? 2 * k : 2 * k + 1;  // the end this piece is left by
    const std::vector<std::size_t>& there = ends_at[node[leave]];
    std::size_t next = leave;
    for (std::size_t e : there)
      if (e != leave) next = e;
    if (next == leave || used[next / 2]) break;  // a free end, or back at the start
    end = next;
  }
  if (c.pieces.size() != local.size()) fail("internal: the chain of " + component_entities(pieces, component) + " was not walked whole");
  const V s = c.segments.front().points.front();
  if (!open && (c.segments.back().points.back() - s).norm() <= tol) {
    c.segments.back().points.back() = s;
    c.closed = true;
  }
  if (local.size() == 1 && local[0].closed && !c.closed)
    fail(local[0].label + " is flagged closed but ends at " + point_text(c.segments.back().points.back()) +
         ", not at its start " + point_text(s) + " (for a periodic SPLINE, rollkin needs the wrapped control points)");
  return c;
}

double distance_to_component(const std::vector<Piece>& pieces, const Component& component, const V& q) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k : component.pieces) {
    const double d = io::distance_to_segments(pieces[k].segments, q);
    if (d < best) best = d;  // (never NaN: a distance that overflowed is no nearer)
  }
  return best;
}

V point_on_component(const std::vector<Piece>& pieces, const Component& component) {
  const Piece& p = pieces[component.pieces.front()];
  return io::segment_point(p.segments[p.segments.size() / 2], 0.5);
}

std::string component_entities(const std::vector<Piece>& pieces, const Component& component, std::size_t limit) {
  std::string s;
  for (std::size_t i = 0; i < component.pieces.size() && i < limit; ++i) s += (i ? ", " : "") + pieces[component.pieces[i]].label;
  if (component.pieces.size() > limit) s += ", ... (" + std::to_string(component.pieces.size()) + " entities)";
  return s;
}

}  // namespace rollkin::io::dxf
