// What a DXF drawing offers as contours (io/contour_listing.hpp): per layer (in file order), the chains its
// entities form (order-free chaining, dxf/chain.cpp, with the join tolerance of that layer's entities, as a
// selection by layer or "near" + layer has), each with the scene selector that picks exactly it.
//
// Selector: {"type": "dxf", "file": BASENAME, "layer": L} when the layer holds one chain; otherwise "near" a
// point on the chain (the middle of its middle segment, else one of 64 points along it) with the layer, when that chain is the nearest to it
// by more than the tie margin of a selection (kDxfNearTie x the layer's size); otherwise "handles" of its
// entities when these form exactly this chain alone; otherwise none (empty): a chain with a branch, or an
// entity that cannot be read (listed as "TYPE HANDLE: why").
#include "detail.hpp"
#include "../segment_geometry.hpp"

#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/input_file.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <set>

namespace rollkin::io {
namespace {

using namespace rollkin::io::dxf;
using json = nlohmann::ordered_json;

/// The arc length of the segments (each on its own: a single segment has no corner).
double length_of(const std::vector<Segment>& segments) {
  double sum = 0;
  for (const Segment& s : segments) sum += BezierPath<double>({s}, false).total_length();
  return sum;
}

/// Points on a chain that "near" may name it by: the middle of its middle segment first, then up to 64 more
/// spread along it (where other chains cross the middle, another point names it).
std::vector<V> near_candidates(const std::vector<Segment>& segments) {
  std::vector<V> at{segment_point(segments[segments.size() / 2], 0.5)};
  const std::size_t count = std::min<std::size_t>(64, 4 * segments.size());
  for (std::size_t k = 0; k < count; ++k) {
    const double u = (k + 0.5) * static_cast<double>(segments.size()) / static_cast<double>(count);
    const std::size_t i = std::min(segments.size() - 1, static_cast<std::size_t>(u));
    at.push_back(segment_point(segments[i], u - static_cast<double>(i)));
  }
  return at;
}

json base_selector(const std::string& file, const std::string& layer) {
  json j;
  j["type"] = "dxf";
  j["file"] = std::filesystem::path(file).filename().string();
  if (!layer.empty()) j["layer"] = layer;
  return j;
}

/// The chains of one layer.
class LayerLister {
 public:
  LayerLister(const Drawing& drawing, std::string file, std::string layer, std::vector<const RawEntity*> entities)
      : drawing_(drawing), file_(std::move(file)), layer_(std::move(layer)), entities_(std::move(entities)) {}

  void list(std::vector<ListedChain>& out) {
    Placer placer(drawing_, file_);
    std::vector<Piece> all;
    for (const RawEntity* e : entities_) {
      try {
        std::vector<Piece> placed;  // all of an entity's pieces, or none
        placer.place(*e, placed);
        for (Piece& p : placed) all.push_back(std::move(p));
      } catch (const InputError& ex) {
        unreadable_.push_back(e->label() + ": " + ex.what());
      }
    }
    for (Piece& p : all)
      if (!p.zero_length) pieces_.push_back(std::move(p));
    std::vector<std::size_t> every(pieces_.size());
    std::iota(every.begin(), every.end(), 0);
    size_ = pieces_size(pieces_, every);
    tol_ = kDxfJoinTolerance * size_;
    chains_ = connected_chains(pieces_, tol_);
    for (const Component& c : chains_) {  // control-point boxes: a lower bound of a chain's distance
      V lo = pieces_[c.pieces.front()].segments.front().points.front(), hi = lo;
      for (std::size_t k : c.pieces)
        for (const Segment& s : pieces_[k].segments)
          for (const V& q : s.points) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
      boxes_.emplace_back(lo, hi);
    }
    for (const Component& c : chains_) out.push_back(listed(c));
    for (const std::string& u : unreadable_) {
      ListedChain bad;
      bad.group = layer_;
      bad.entities = {u};
      out.push_back(bad);
    }
  }

 private:
  ListedChain listed(const Component& c) const {
    ListedChain l;
    l.group = layer_;
    Chain chain;
    try {
      chain = walk_chain(file_, pieces_, c, tol_, size_);
    } catch (const InputError& ex) {  // a branch: listed with its entities, not selectable as one contour
      for (std::size_t k : c.pieces) {
        l.entities.push_back(pieces_[k].label);
        for (const Segment& s : pieces_[k].segments) l.segments.push_back(s);
      }
      l.entities.push_back(std::string("(not one contour: ") + ex.what() + ")");
      l.length = length_of(l.segments);
      segments_box(l.segments, l.min, l.max);
      return l;
    }
    for (std::size_t k : chain.pieces) l.entities.push_back(pieces_[k].label);
    l.closed = chain.closed;
    l.segments = chain.segments;
    l.length = length_of(l.segments);
    segments_box(l.segments, l.min, l.max);
    const BezierPathOptions<double> options;
    l.corners = path_corners(l.segments, l.closed, options.joint_tolerance * pieces_size(pieces_, c.pieces), options.corner_tolerance).size();
    l.selector = selector(c, l.segments);
    return l;
  }

  /// The selector that picks exactly this chain (see the file's comment), or empty.
  std::string selector(const Component& c, const std::vector<Segment>& segments) const {
    if (unreadable_.empty()) {
      if (chains_.size() == 1) return base_selector(file_, layer_).dump();
      for (const V& at : near_candidates(segments))
        if (nearest_alone(c, at)) {
          json j = base_selector(file_, layer_);
          j["near"] = {at.x(), at.y()};
          return j.dump();
        }
    }
    std::vector<std::string> handles;
    for (std::size_t k : c.pieces) {
      if (pieces_[k].handle.empty()) return "";
      if (std::find(handles.begin(), handles.end(), pieces_[k].handle) == handles.end()) handles.push_back(pieces_[k].handle);
    }
    if (!handles_make_only(c, handles)) return "";
    json j = base_selector(file_, "");
    j["handles"] = handles;
    return j.dump();
  }

  /// Whether `at` picks component c among the layer's chains ("near" with "layer": the same pieces, tolerance
  /// and tie margin as the selection).
  bool nearest_alone(const Component& c, const V& at) const {
    const double mine = distance_to_component(pieces_, c, at), margin = mine + kDxfNearTie * size_;
    for (std::size_t i = 0; i < chains_.size(); ++i) {
      const Component& other = chains_[i];
      const V outside = (boxes_[i].first - at).cwiseMax(at - boxes_[i].second).cwiseMax(V(0, 0));
      if (&other == &c || outside.norm() > margin) continue;  // farther than the margin: cannot tie
      if (distance_to_component(pieces_, other, at) <= margin) return false;
    }
    return true;
  }

  /// Whether the entities with these handles (everything they place) form exactly the pieces of c, in one chain
  /// (with the tolerance such a selection has: of these pieces alone).
  bool handles_make_only(const Component& c, const std::vector<std::string>& handles) const {
    const std::set<std::string> wanted(handles.begin(), handles.end());
    std::vector<std::size_t> of;
    for (std::size_t k = 0; k < pieces_.size(); ++k)
      if (wanted.count(pieces_[k].handle)) of.push_back(k);
    if (of != c.pieces) return false;
    std::vector<Piece> alone;
    for (std::size_t k : of) alone.push_back(pieces_[k]);
    std::vector<std::size_t> every(alone.size());
    std::iota(every.begin(), every.end(), 0);
    const std::vector<Component> parts = connected_chains(alone, kDxfJoinTolerance * pieces_size(alone, every));
    return parts.size() == 1 && parts[0].branch.empty();
  }

  const Drawing& drawing_;
  std::string file_, layer_;
  std::vector<const RawEntity*> entities_;
  std::vector<Piece> pieces_;
  std::vector<std::string> unreadable_;
  std::vector<Component> chains_;
  std::vector<std::pair<V, V>> boxes_;  // per chain: its control points' box
  double size_ = 0, tol_ = 0;
};

}  // namespace

std::vector<ListedChain> list_dxf_contours(const std::string& path) {
  const Drawing drawing = read_drawing(read_input_file(path, "the DXF file"), path, path);
  check_drawing(drawing, path);
  std::vector<std::string> layers;  // first spelling, file order; compared case-insensitively
  std::vector<std::vector<const RawEntity*>> on;
  for (const RawEntity* e : drawing.top_level()) {
    if (never_a_curve(e->type)) continue;
    const auto it = std::find_if(layers.begin(), layers.end(), [&](const std::string& l) { return upper(l) == upper(e->layer); });
    const std::size_t index = static_cast<std::size_t>(it - layers.begin());
    if (index == layers.size()) {
      layers.push_back(e->layer);
      on.emplace_back();
    }
    on[index].push_back(e);
  }
  std::vector<ListedChain> out;
  for (std::size_t i = 0; i < layers.size(); ++i) LayerLister(drawing, path, layers[i], on[i]).list(out);
  return out;
}

}  // namespace rollkin::io
