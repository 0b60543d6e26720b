// What a DXF drawing offers as contours (io/contour_listing.hpp): per layer (in file order), the chains its
// entities form (order-free chaining, dxf/chain.cpp, with the join tolerance of that layer's entities, as a
// selection by layer or "near" + layer has), each with the scene selector that picks exactly it.
//
// Selector: {"type": "dxf", "file": PATH, "layer": L} when the layer holds one chain; otherwise "near" a
// point on the chain (the middle of its middle segment, else one of 64 points along it) with the layer, when that
// chain is the nearest to it by more than the tie margin of a selection (kDxfNearTie x the layer's size);
// otherwise "handles" of its entities when these form exactly this chain alone; otherwise none, with the reason
// (ListedChain::no_selector): a chain with a branch, entities without handles or whose handles place more. An
// entity that cannot be read is listed as unreadable with its message, after its layer's chains.
// Cost: n log n in the layer's pieces (docs/reliability.md, "CAD readers (issue 37)"): the other chains near a
// point come from an R-tree of segment boxes (SegmentIndex), the pieces of a handle from one map.
#include "detail.hpp"
#include "../segment_geometry.hpp"

#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/input_file.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <numeric>
#include <optional>

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

/// The selector's text, or nullopt when a name in it is not UTF-8 text (a layer name in another code page),
/// which a scene, JSON, cannot hold.
std::optional<std::string> dumped(const json& j) {
  try {
    return j.dump();
  } catch (const json::type_error&) {
    return std::nullopt;
  }
}

json base_selector(const std::string& file, const std::string& layer) {
  json j;
  j["type"] = "dxf";
  j["file"] = file;  // the path as given, as every format's selector (README, "contours")
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
        unreadable_.push_back({e->label(), ex.what()});
      }
    }
    for (Piece& p : all)
      if (!p.zero_length) pieces_.push_back(std::move(p));
    std::vector<std::size_t> every(pieces_.size());
    std::iota(every.begin(), every.end(), 0);
    size_ = pieces_size(pieces_, every);
    tol_ = kDxfJoinTolerance * size_;
    chains_ = connected_chains(pieces_, tol_);
    std::vector<std::pair<const Segment*, std::size_t>> segments;  // every segment with its chain
    for (std::size_t i = 0; i < chains_.size(); ++i)
      for (std::size_t k : chains_[i].pieces)
        for (const Segment& s : pieces_[k].segments) segments.emplace_back(&s, i);
    index_ = std::make_unique<SegmentIndex>(segments);
    for (std::size_t k = 0; k < pieces_.size(); ++k) by_handle_[upper(pieces_[k].handle)].push_back(k);
    for (std::size_t i = 0; i < chains_.size(); ++i) out.push_back(listed(i));
    for (const auto& [label, message] : unreadable_) {
      ListedChain bad;
      bad.group = layer_;
      bad.entities = {label};
      bad.unreadable = message;
      bad.no_selector = "it cannot be read (see its message)";
      out.push_back(bad);
    }
  }

 private:
  ListedChain listed(std::size_t i) const {
    const Component& c = chains_[i];
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
      l.no_selector = std::string("not one contour: ") + ex.what();
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
    l.selector = selector(i, l.segments, l.no_selector);
    return l;
  }

  /// The selector that picks exactly chain i (see the file's comment), or empty with `why`.
  std::string selector(std::size_t i, const std::vector<Segment>& segments, std::string& why) const {
    const Component& c = chains_[i];
    std::string by_layer;  // why neither the layer nor "near" picks it
    if (!unreadable_.empty()) {
      by_layer = "the layer also holds " + std::to_string(unreadable_.size()) + " unreadable entit" +
                 (unreadable_.size() == 1 ? "y" : "ies") + " (listed), which a selection by layer or \"near\" reads too";
    } else if (chains_.size() == 1) {
      if (const auto j = dumped(base_selector(file_, layer_))) return *j;
      by_layer = "the layer's or the file's name is not UTF-8 text, which a scene (JSON) cannot hold";
    } else {
      by_layer = "no point along it is nearer to it than to the layer's other chains by the tie margin";
      for (const V& at : near_candidates(segments))
        if (nearest_alone(i, at)) {
          json j = base_selector(file_, layer_);
          j["near"] = {at.x(), at.y()};
          if (const auto text = dumped(j)) return *text;
          by_layer = "the layer's or the file's name is not UTF-8 text, which a scene (JSON) cannot hold";
          break;
        }
    }
    std::vector<std::string> handles;
    for (std::size_t k : c.pieces) {
      if (pieces_[k].handle.empty()) {
        why = by_layer + "; and " + pieces_[k].label + " has no handle (group 5): give the entities handles (a CAD "
              "program's save does) or move the chain to a layer of its own";
        return "";
      }
      if (std::find(handles.begin(), handles.end(), pieces_[k].handle) == handles.end()) handles.push_back(pieces_[k].handle);
    }
    if (!handles_make_only(c, handles)) {
      why = by_layer + "; and the handles of its entities also name other pieces (an INSERT's other copies, or an "
            "entity sharing a handle): move the chain to a layer of its own, or explode the INSERT";
      return "";
    }
    json j = base_selector(file_, "");
    j["handles"] = handles;
    if (const auto text = dumped(j)) return *text;
    why = by_layer + "; and a handle is not UTF-8 text";
    return "";
  }

  /// Whether `at` picks chain i among the layer's chains ("near" with "layer": the same pieces, tolerance and
  /// tie margin as the selection): no other chain passes within its distance plus the margin.
  bool nearest_alone(std::size_t i, const V& at) const {
    const double mine = distance_to_component(pieces_, chains_[i], at);
    return !index_->other_within(at, mine + kDxfNearTie * size_, i);
  }

  /// Whether the entities with these handles (everything they place) form exactly the pieces of c, in one chain
  /// (with the tolerance such a selection has: of these pieces alone). Handles compared case-insensitively, as
  /// the selection compares them.
  bool handles_make_only(const Component& c, const std::vector<std::string>& handles) const {
    std::vector<std::size_t> of;
    for (const std::string& h : handles) {
      const std::vector<std::size_t>& with = by_handle_.at(upper(h));
      of.insert(of.end(), with.begin(), with.end());
      if (of.size() > c.pieces.size()) return false;  // more than this chain: stop before copying them all
    }
    std::sort(of.begin(), of.end());
    of.erase(std::unique(of.begin(), of.end()), of.end());
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
  std::vector<std::pair<std::string, std::string>> unreadable_;  // entity label, message
  std::vector<Component> chains_;
  std::unique_ptr<SegmentIndex> index_;                     // every segment with its chain
  std::map<std::string, std::vector<std::size_t>> by_handle_;  // upper-case handle -> its pieces, in order
  double size_ = 0, tol_ = 0;
};

}  // namespace

std::vector<ListedChain> list_dxf_contours(const std::string& path) {
  const Drawing drawing = read_drawing(read_input_file(path, "the DXF file"), path, path);
  check_drawing(drawing, path);
  std::vector<std::string> layers;  // first spelling, file order; compared case-insensitively
  std::map<std::string, std::size_t> layer_index;  // upper-case name -> index in layers
  std::vector<std::vector<const RawEntity*>> on;
  for (const RawEntity* e : drawing.top_level()) {
    if (never_a_curve(e->type)) continue;
    const auto [it, fresh] = layer_index.emplace(upper(e->layer), layers.size());
    if (fresh) {
      layers.push_back(e->layer);
      on.emplace_back();
    }
    on[it->second].push_back(e);
  }
  std::vector<ListedChain> out;
  for (std::size_t i = 0; i < layers.size(); ++i) LayerLister(drawing, path, layers[i], on[i]).list(out);
  return out;
}

}  // namespace rollkin::io
