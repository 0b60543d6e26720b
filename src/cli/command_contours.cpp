// `rollkin contours FILE [--draw OUT.svg] [--json]`: what a drawing or point file offers as contours, by its
// format (io/contour_formats.hpp, io/contour_listing.hpp): per chain its group (DXF layer, SVG element, file),
// entities, closed or open, length, bounding box, corners and the contour object that selects it in a scene.
#include "commands.hpp"

#include "rollkin/io/contour_formats.hpp"
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/output/contour_picture.hpp"

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
  CLI::App* app = rollkin.add_subcommand("contours", "list the contours a drawing or point file offers, with the scene "
                                                     "snippet that selects each");
  app->add_option("FILE", o->file, "the file: a " + io::contour_file_extensions() + " file")->required()->type_name("");
  add_output(*app, "--draw", o->draw, "write an SVG picture of the drawing with every chain numbered as listed");
  app->add_flag("--json", o->json, "print the list as a JSON array instead of text");
  // The formats and what is listed of each come from the table of contour file formats (io/contour_formats.hpp).
  app->footer(
      "Lists every chain of the file, by its format (the extension, case ignored):\n" + io::contour_file_formats_help() +
      "Per chain: its group (layer, element or file), entities, closed or open, length, bounding box and corners\n"
      "in the file's units (SVG: viewport units, y up, as a scene without units.length reads them), and the contour\n"
      "object that selects exactly it: paste it into a scene's \"contours\" with a \"name\" (its \"file\" is the\n"
      "path given here: make it relative to the scene's directory). README.md, \"rollkin contours\".\n"
      "Exit status: 0 listed; 2 bad input (a file that cannot be read: the message names the file, the element,\n"
      "entity or line and what to change) or command line, nothing written; 3 out of memory.");
  return {app, [o] { return run_contours(*o); }};
}

namespace {

std::string box_text(const io::ListedChain& c) {
  return "(" + io::format_number(c.min.x(), 10) + ", " + io::format_number(c.min.y(), 10) + ") to (" + io::format_number(c.max.x(), 10) + ", " +
         io::format_number(c.max.y(), 10) + ")";
}

nlohmann::ordered_json chain_json(const io::ListedChain& c) {
  nlohmann::ordered_json j;
  j["group"] = c.group;
  j["entities"] = c.entities;
  j["closed"] = c.closed;
  j["length"] = c.length;
  j["min"] = {c.min.x(), c.min.y()};
  j["max"] = {c.max.x(), c.max.y()};
  j["corners"] = c.corners;
  j["selector"] = nlohmann::ordered_json::parse(c.selector);
  return j;
}

int run_contours(const ContoursOptions& o) {
  io::OutputSet outputs({o.file});
  const std::size_t draw = o.draw.empty() ? 0 : outputs.add("--draw", o.draw);  // checked before reading
  g_doing = "reading the drawing";
  const std::vector<io::ListedChain> chains = io::list_contours(o.file);
  if (o.json) {
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (const auto& c : chains) all.push_back(chain_json(c));
    std::cout << all.dump(2) << "\n";
  } else {
    std::cout << o.file << ": " << chains.size() << " chain(s)\n";
    for (std::size_t k = 0; k < chains.size(); ++k) {
      const io::ListedChain& c = chains[k];
      std::string entities;
      for (const auto& e : c.entities) entities += (entities.empty() ? "" : ", ") + e;
      std::cout << k + 1 << ". " << c.group << ": " << entities << "; " << (c.closed ? "closed" : "open") << ", length "
                << io::format_number(c.length, 10) << ", box " << box_text(c) << ", " << c.corners << " corner(s)\n   "
                << c.selector << "\n";
    }
  }
  if (!o.draw.empty()) {
    outputs.set(draw, output::contour_listing_svg(o.file, chains));
    outputs.commit();
  }
  return 0;
}

}  // namespace
}  // namespace rollkin::cli
