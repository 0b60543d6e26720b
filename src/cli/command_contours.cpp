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
      "An SVG element hidden by display=\"none\" or visibility=\"hidden\" is marked hidden: \"near\" and \"subpath\"\n"
      "pass it over, only its own id selects it. Per chain: its group (layer, element or file), entities, closed or\n"
      "open, length, bounding box and corners in the file's units (SVG: viewport units, y up, as a scene without\n"
      "units.length reads them), and the contour object that selects exactly it: paste it into a scene's\n"
      "\"contours\" with a \"name\" (its \"file\" is the path given here: make it relative to the scene's\n"
      "directory); a chain no selector picks says why. An entity or element that cannot be read is listed as\n"
      "unreadable with its message (no length, no box).\n"
      "Exit status: 0 listed; 2 bad input (a file that cannot be read, or one with unreadable entities: listed,\n"
      "then named on stderr; --draw not written) or command line, nothing written; 3 out of memory.");
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
    outputs.set(draw, output::contour_listing_svg(o.file, chains));
    outputs.commit();
  }
  return 0;
}

}  // namespace
}  // namespace rollkin::cli
