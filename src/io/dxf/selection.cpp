// DXF contour reader (io/dxf/reader.hpp), the selection: which entities of the drawing (dxf/drawing.cpp) form the
// contour (io/dxf/reader.hpp, "Selection"), their pieces grouped into chains (dxf/chain.cpp) and the one chain picked
// and walked into a DxfContour; the entry points parse_dxf_contour and read_dxf_contour.
#include "detail.hpp"

#include "rollkin/io/input_file.hpp"
#include "rollkin/io/units.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <limits>
#include <optional>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <sstream>

namespace rollkin::io {

using namespace dxf;

namespace {

/// Exactly one way of selecting (io/dxf/reader.hpp, "Selection").
void check_selection(const DxfSelection& sel, const std::string& file) {
  const bool by_handle = !sel.handle.empty(), by_handles = !sel.handles.empty(), by_layer = !sel.layer.empty();
  const int ways = int(by_handle) + int(by_handles) + int(by_layer || sel.near.has_value());
  if (ways != 1)
    throw InputError(file, "",
                     "select the contour by a layer name (optionally with a point \"near\" it), by a point \"near\" it, "
                     "by one entity handle or by a list of handles (exactly one of these)");
  if (sel.near && !(std::isfinite(sel.near->x()) && std::isfinite(sel.near->y())))
    throw InputError(file, "", "the point \"near\" must be finite");
}

/// The entities of the ENTITIES section the selection considers.
std::vector<const RawEntity*> considered(const std::vector<const RawEntity*>& all, const DxfSelection& sel, const std::string& file) {
  std::vector<const RawEntity*> chosen;
  std::vector<std::string> handles = sel.handles;
  if (!sel.handle.empty()) handles.push_back(sel.handle);
  if (!handles.empty()) {
    std::map<std::string, std::vector<const RawEntity*>> by_handle;
    for (const RawEntity* e : all)
      if (!e->handle.empty()) by_handle[upper(e->handle)].push_back(e);
    std::set<const RawEntity*> taken;
    for (const std::string& h : handles) {
      const auto found = by_handle.find(upper(h));
      if (found == by_handle.end()) throw InputError(file, "", "no entity with handle " + h + " in the ENTITIES section");
      check_one_entity(h, found->second, file);
      const auto it = found->second.begin();
      if (never_a_curve((*it)->type))
        throw InputError(file, "handle " + h, (*it)->label() + " is not a curve; a contour is made of " + std::string(kSupported));
      if (taken.insert(*it).second) chosen.push_back(*it);
    }
    // in file order, whatever the order of the list: a chain is walked alike however it is selected
    std::sort(chosen.begin(), chosen.end(), [](const RawEntity* a, const RawEntity* b) { return a->line < b->line; });
    return chosen;
  }
  for (const RawEntity* e : all)
    if (sel.layer.empty() || upper(e->layer) == upper(sel.layer)) chosen.push_back(e);
  if (chosen.empty()) {
    std::vector<std::string> layers;
    for (const RawEntity* e : all)
      if (std::find(layers.begin(), layers.end(), e->layer) == layers.end()) layers.push_back(e->layer);
    std::string known;
    for (std::size_t i = 0; i < layers.size() && i < 20; ++i) known += (i ? ", \"" : "\"") + layers[i] + "\"";
    throw InputError(file, "",
                     sel.layer.empty() ? "no entity in the ENTITIES section"
                                       : "no entity on layer \"" + sel.layer + "\" in the ENTITIES section (layers with entities: " +
                                             (known.empty() ? "none" : known) + ")");
  }
  return chosen;
}

/// The pieces of the considered entities; zero-length LINEs are dropped (noted) unless they are all there is.
std::vector<Piece> pieces_of(const Drawing& drawing, const std::vector<const RawEntity*>& chosen, const DxfSelection& sel,
                             const std::string& file, std::vector<std::string>& notes) {
  std::string unsupported;
  for (const RawEntity* e : chosen)
    if (e->type != "INSERT" && !never_a_curve(e->type) && (!supported(e->type) || !e->delivered))
      unsupported += (unsupported.empty() ? "" : ", ") + e->label() + " (line " + std::to_string(e->line) + ")";
  if (!unsupported.empty())
    throw InputError(file, selection_text(sel),
                     "unsupported entities: " + unsupported + "; a contour is made of " + kSupported +
                         " (move the others to another layer, or select the contour with \"near\" on a layer without them "
                         "or with \"handles\")");
  Placer placer(drawing, file);
  std::vector<Piece> all;
  for (const RawEntity* e : chosen) placer.place(*e, all);
  std::vector<Piece> kept;
  for (Piece& p : all) {
    if (!p.zero_length) kept.push_back(std::move(p));
    else notes.push_back(p.label + " has zero length: dropped");
  }
  if (kept.empty()) {
    if (!all.empty()) throw InputError(file, selection_text(sel), all.front().label + " has zero length");
    throw InputError(file, selection_text(sel), "no curve entities selected (only text, dimensions and the like); a contour is made of " +
                                                    std::string(kSupported));
  }
  return kept;
}

/// The chains, one a line, each with a point on it (for "near") and its entities.
std::string chains_text(const std::vector<Piece>& pieces, const std::vector<Component>& chains, std::size_t limit = 12) {
  std::string s;
  for (std::size_t i = 0; i < chains.size() && i < limit; ++i)
    s += "\n  chain " + std::to_string(i + 1) + ": through " + point_text(point_on_component(pieces, chains[i])) + ": " +
         component_entities(pieces, chains[i]);
  if (chains.size() > limit) s += "\n  ... (" + std::to_string(chains.size()) + " chains)";
  return s;
}

/// The component the selection names: the only one, or the one nearest to `near`.
std::size_t pick_chain(const std::vector<Piece>& pieces, const std::vector<Component>& chains, const DxfSelection& sel,
                       double size, const std::string& file) {
  if (sel.near) {
    std::vector<std::pair<double, std::size_t>> d;
    for (std::size_t i = 0; i < chains.size(); ++i) d.emplace_back(distance_to_component(pieces, chains[i], *sel.near), i);
    std::sort(d.begin(), d.end());
    if (d.size() > 1 && d[1].first - d[0].first <= kDxfNearTie * size)
      throw InputError(file, selection_text(sel),
                       "two chains pass about equally near " + point_text(*sel.near) + " (distances " + number(d[0].first) +
                           " and " + number(d[1].first) + ", within " + number(kDxfNearTie) + " x the drawing size " +
                           number(size) + "): " + component_entities(pieces, chains[d[0].second]) + ", and " +
                           component_entities(pieces, chains[d[1].second]) +
                           "; give a point nearer to the one you mean (a point on it), or its \"handles\"");
    return d[0].second;
  }
  if (chains.size() > 1) {
    const std::string what = sel.handle.empty() && sel.handles.empty() ? "the entities on " + selection_text(sel) : "the entities of " + selection_text(sel);
    throw InputError(file, selection_text(sel),
                     what + " form " + std::to_string(chains.size()) + " chains, not one:" + chains_text(pieces, chains) +
                         "\nselect one with \"near\": [x, y] (a point on or near it, drawing units) or \"handles\": [...], "
                         "or list them with `rollkin contours " + (file.empty() ? std::string("FILE") : file) + "`");
  }
  return 0;
}

std::string describe(const DxfContour& out, const DxfSelection& sel, const std::string& file) {
  std::ostringstream os;
  os << "DXF " << (file.empty() ? std::string("<text>") : file) << " " << selection_text(sel) << ": " << out.entities.size()
     << (out.entities.size() == 1 ? " entity (" : " entities (");
  for (std::size_t i = 0; i < out.entities.size() && i < 4; ++i) os << (i ? ", " : "") << out.entities[i];
  if (out.entities.size() > 4) os << ", ...";
  os << "), " << out.segments.size() << " segments, " << (out.closed ? "closed" : "open") << ", " << out.corners.size()
     << (out.corners.size() == 1 ? " corner, " : " corners, ")
     << (out.unit.empty() ? std::string("unitless") : "unit " + out.unit + " (" + number(out.metres_per_unit) + " m)");
  for (const std::string& n : out.notes) os << "; " << n;
  return os.str();
}

/// The selected chain as a DxfContour.
DxfContour contour_from(const std::string& text, const std::string& disk_path, const DxfSelection& selection,
                        const std::string& file) {
  const Drawing drawing = read_drawing(text, disk_path, file);
  DxfContour out;
  set_units(out, drawing, file);
  check_selection(selection, file);
  const std::vector<const RawEntity*> top = drawing.top_level();
  const std::vector<Piece> pieces = pieces_of(drawing, considered(top, selection, file), selection, file, out.notes);
  std::vector<std::size_t> every(pieces.size());
  std::iota(every.begin(), every.end(), 0);
  const double size = pieces_size(pieces, every), tol = kDxfJoinTolerance * size;
  const std::vector<Component> chains = connected_chains(pieces, tol);
  const Component& picked = chains[pick_chain(pieces, chains, selection, size, file)];
  Chain chain = walk_chain(file, pieces, picked, tol, size);
  out.segments = std::move(chain.segments);
  out.closed = chain.closed;
  for (std::size_t k : chain.pieces) out.entities.push_back(pieces[k].label);

  const std::size_t n = out.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = chain.owner[(i + n - 1) % n], after = chain.owner[i];
    out.joint_entities.push_back(before == after ? pieces[after].label : pieces[before].label + " / " + pieces[after].label);
  }
  const BezierPathOptions<double> options;
  const double chain_size = pieces_size(pieces, picked.pieces);
  for (const PathCorner<double>& k : path_corners(out.segments, out.closed, options.joint_tolerance * chain_size, options.corner_tolerance))
    out.corners.push_back({out.joint_entities[k.piece], k.piece, k.point, rad_to_deg(k.turn)});
  out.description = describe(out, selection, file);
  return out;
}

}  // namespace

std::string selection_text(const DxfSelection& sel) {
  if (!sel.handle.empty()) return "handle " + sel.handle;
  if (!sel.handles.empty()) {
    std::string s = "handles ";
    for (std::size_t i = 0; i < sel.handles.size(); ++i) s += (i ? ", " : "") + sel.handles[i];
    return s;
  }
  std::string s = sel.layer.empty() ? std::string("all layers") : "layer \"" + sel.layer + "\"";
  if (sel.near) s += ", near " + point_text(*sel.near);
  return s;
}

DxfContour parse_dxf_contour(const std::string& dxf, const DxfSelection& selection, const std::string& file) {
  return contour_from(dxf, "", selection, file);
}

DxfContour read_dxf_contour(const std::string& path, const DxfSelection& selection) {
  return contour_from(io::read_input_file(path, "the DXF file"), path, selection, path);
}

}  // namespace rollkin::io
