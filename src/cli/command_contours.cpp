// `rollkin contours FILE.dxf|FILE.svg [--draw OUT.svg] [--json]`: what a drawing offers as contours
// (io/contour_listing.hpp): per chain its group (DXF layer, SVG element), entities, closed or open, length,
// bounding box, corners and the contour object that selects it in a scene (README, "The command-line tool";
// docs/scene_format.md, "Command line and outputs").
#include "commands.hpp"

#include "rollkin/io/contour_listing.hpp"
#include "rollkin/output/svg_drawing.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace rollkin::cli {
namespace {

struct ContoursOptions {
  std::string file, draw;
  bool json = false;
};

int run_contours(const ContoursOptions& o);

}  // namespace

Command contours_command(CLI::App& rollkin) {
  auto o = std::make_shared<ContoursOptions>();
  CLI::App* app = rollkin.add_subcommand("contours", "list the contours a DXF or SVG drawing offers, with the scene "
                                                     "snippet that selects each");
  app->add_option("FILE", o->file, "the drawing: a .dxf or .svg file")->required()->type_name("");
  add_output(*app, "--draw", o->draw, "write an SVG picture of the drawing with every chain numbered as listed");
  app->add_flag("--json", o->json, "print the list as a JSON array instead of text");
  app->footer(
      "Lists every chain of the drawing: DXF, per layer, the chains the entities form end to end; SVG, every\n"
      "subpath of every element (<use> clones, <symbol>, <switch> expanded; an element hidden by display=\"none\"\n"
      "or visibility=\"hidden\" is marked hidden: \"near\" and \"subpath\" pass it over, only its own id selects\n"
      "it). Per chain: its group (layer or element), entities, closed or open, length, bounding box and corners\n"
      "in drawing units (SVG: viewport units, y up, as a scene without units.length reads them), and the contour\n"
      "object that selects exactly it: paste it into a scene's \"contours\" with a \"name\" (its \"file\" is the\n"
      "path given here: make it relative to the scene's directory); a chain no selector picks says why.\n"
      "An entity or element that cannot be read is listed as unreadable with its message (no length, no box).\n"
      "README, \"The command-line tool\"; docs/scene_format.md, \"SVG contours\" and \"`dxf` contours\".\n"
      "Exit status: 0 listed; 2 bad input (a drawing that cannot be read, or one with unreadable entities:\n"
      "listed, then named on stderr; --draw not written) or command line, nothing written; 3 out of memory.");
  return {app, [o] { return run_contours(*o); }};
}

namespace {

std::string box_text(const io::ListedChain& c) {
  return "(" + io::format_number(c.min.x(), 10) + ", " + io::format_number(c.min.y(), 10) + ") to (" + io::format_number(c.max.x(), 10) + ", " +
         io::format_number(c.max.y(), 10) + ")";
}

/// One listed chain as text: "k. group: entities; closed, length, box, corners" and its selector (or why
/// there is none); an unreadable entity with its message.
std::string chain_text(std::size_t k, const io::ListedChain& c) {
  std::string entities;
  for (const auto& e : c.entities) entities += (entities.empty() ? "" : ", ") + e;
  const std::string number = std::to_string(k + 1) + ". " + c.group + ": ";
  if (!c.unreadable.empty()) return number + "unreadable: " + c.unreadable + "\n";
  return number + entities + "; " + (c.closed ? "closed" : "open") + ", length " + io::format_number(c.length, 10) +
         ", box " + box_text(c) + ", " + std::to_string(c.corners) + " corner(s)" +
         (c.hidden.empty() ? "" : ", hidden: " + c.hidden) + "\n   " +
         (c.selector.empty() ? "(no selector: " + c.no_selector + ")" : c.selector) + "\n";
}

/// The drawing with every chain in its own colour and numbered at its start, as listed.
std::string picture(const std::string& file, const std::vector<io::ListedChain>& chains) {
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  io::SvgDrawing d(900, 700, 30);
  d.set_title(fs::path(file).filename().string() + ": " + std::to_string(chains.size()) + " chain(s)");
  for (std::size_t k = 0; k < chains.size(); ++k) {
    const io::ListedChain& c = chains[k];
    if (c.segments.empty()) continue;  // an unreadable entity: nothing to draw
    std::vector<Eigen::Vector2d> points;
    for (const auto& s : c.segments) {
      BezierPath<double> piece({s}, false);
      for (int i = (points.empty() ? 0 : 1); i <= 24; ++i) points.push_back(piece.jet(i / 24.0, 0).p);
    }
    io::Stroke st;
    st.color = colours[k % (sizeof colours / sizeof *colours)];
    st.width = 1.4;
    d.add_polyline(points, st, c.closed);
    d.add_point(points.front(), st.color, 3.0);
    d.add_text(points.front(), std::to_string(k + 1), 11.0, st.color);
  }
  return d.to_svg();
}

int run_contours(const ContoursOptions& o) {
  io::OutputSet outputs({o.file});
  const std::size_t draw = o.draw.empty() ? 0 : outputs.add("--draw", o.draw);  // checked before reading
  g_doing = "reading the drawing";
  const std::vector<io::ListedChain> chains = io::list_contours(o.file);
  if (o.json) {
    std::cout << io::contours_json(chains) << "\n";
  } else {
    std::cout << o.file << ": " << chains.size() << " chain(s)\n";
    for (std::size_t k = 0; k < chains.size(); ++k) std::cout << chain_text(k, chains[k]);
  }
  if (const std::size_t bad = io::unreadable_count(chains)) {
    std::cerr << "rollkin contours: " << o.file << ": " << bad << (bad == 1 ? " entity or element" : " entities or elements")
              << " could not be read (listed above as unreadable, each with its message); the other chains are listed";
    if (!o.draw.empty()) std::cerr << "; " << o.draw << " not written";
    std::cerr << "\n";
    return 2;
  }
  if (!o.draw.empty()) {
    outputs.set(draw, picture(o.file, chains));
    outputs.commit();
  }
  return 0;
}

}  // namespace
}  // namespace rollkin::cli
