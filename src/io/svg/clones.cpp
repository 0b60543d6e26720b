// SVG documents, what an element draws (io/svg/reader.hpp, "What an element draws"): the rendering tree below
// it walked with <use> clones expanded (SVG 2, 5.6), <symbol>s drawn through their viewBox (SVG 1.1, 5.5,
// 7.8) and each <switch> drawing its first child whose conditions hold (SVG 1.1, 5.8.2); the element's
// ancestors checked to draw it at all.
#include "document.hpp"

namespace rollkin::io::svg_detail {
namespace {

std::string href_of(const pugi::xml_node& use) {
  for (const char* name : {"href", "xlink:href"})
    if (const pugi::xml_attribute a = use.attribute(name)) return trimmed(a.value());
  return "";
}

/// The child a <switch> draws: its first direct child that renders and whose conditions hold (SVG 1.1, 5.8.2;
/// requiredExtensions: rollkin supports none, so any value fails; requiredFeatures always holds, as in SVG 2;
/// systemLanguage depends on the viewer and is an error). Null when none does.
pugi::xml_node switch_choice(const pugi::xml_node& sw, const Document& doc) {
  for (const pugi::xml_node c : sw.children()) {
    if (c.type() != pugi::node_element) continue;
    const std::string kind = local_name(c);
    if (!renders(kind)) continue;
    if (c.attribute("requiredExtensions")) continue;
    if (const pugi::xml_attribute lang = c.attribute("systemLanguage"))
      doc.where(c).fail("which child of the <switch> (" + doc.location(sw) + ") is drawn depends on the viewer's "
                        "language (systemLanguage=\"" + std::string(lang.value()) + "\"); take the element you mean "
                        "out of the <switch>");
    if (kind == element::foreign_object)
      doc.where(c).fail("the <switch> (" + doc.location(sw) + ") draws a <foreignObject>, which has no contour. "
                        "Illustrator writes such a switch with \"Preserve Illustrator Editing Capabilities\": save "
                        "the SVG with that option turned off");
    return c;
  }
  return pugi::xml_node{};
}

/// Bounds of the walk: <use> nesting (clones of clones multiply), the count of drawn shapes, and the nesting of
/// elements below the selected one (the walk recurses: 256 levels keep it far inside the stack also under
/// AddressSanitizer, whose frames are several times larger; at 2000 its 8 MB overflowed).
constexpr std::size_t kMaxUseDepth = 32;
constexpr std::size_t kMaxDrawn = 100000;
constexpr std::size_t kMaxNesting = 256;

/// Walks the rendering tree below an element, expanding <use> and <switch> (SVG 1.1, 5.6, 5.8.2).
class DrawnCollector {
 public:
  explicit DrawnCollector(const Document& doc) : doc_(doc) {}

  /// The element drawn with `parent` mapping its parent's coordinates to the root's. `owner`: its innermost
  /// ancestor in the document tree that draws it (in set.owners), when it is drawn in place. `hiding`: what
  /// its ancestors' display and visibility say; its own are applied unless `selected` (the element the user
  /// named: drawn whatever hides it, document.hpp, Hiding).
  void element(const pugi::xml_node& n, const Affine& parent, std::size_t transforms, std::size_t owner,
               const Hiding& hiding, bool selected = false, std::size_t depth = 0) {
    const std::string kind = local_name(n);
    if (depth > kMaxNesting)
      doc_.where(n).fail("is nested more than " + std::to_string(kMaxNesting) + " elements deep below the selected "
                         "element, which rollkin does not walk; select an element further in, or ungroup in the editor");
    if (kind == element::svg && n != doc_.root)
      doc_.where(n).fail("is a nested <svg> viewport, which rollkin does not apply; ungroup it in the editor");
    if (!is_container(kind) && !is_shape(kind) && kind != element::use) return;  // not drawn, or nothing with a contour
    const std::size_t mine = uses_.empty() ? set.owners.add(n, owner) : owner;
    const OwnRendering own = own_rendering(n, doc_);  // checked also where it is not applied
    const Hiding here = selected ? hiding : hiding.below(own, uses_.empty() ? mine : Hiding::inside);
    const Affine m = parent * own_transform(n, doc_, transforms);
    if (is_shape(kind)) {
      if (set.drawn.size() >= kMaxDrawn)
        doc_.where(n).fail("draws more than " + std::to_string(kMaxDrawn) + " shapes (through nested <use>); "
                           "select one group or clone by its id");
      set.drawn.push_back({n, m, transforms, via_, uses_.empty() ? mine : use_owner_, here.why(), here.hider()});
      return;
    }
    if (kind == element::use) return use(n, m, transforms, mine, here, depth);
    if (const std::string e = unexpanded_entity(doc_, n); !e.empty()) doc_.where(n).fail(e);
    if (kind == element::switch_) {
      if (const pugi::xml_node c = switch_choice(n, doc_)) element(c, m, transforms, mine, here, false, depth + 1);
      return;
    }
    for (const pugi::xml_node c : n.children())
      if (c.type() == pugi::node_element) element(c, m, transforms, mine, here, false, depth + 1);
  }

  DrawnSet set;

 private:
  /// <use>: its transform, then translate(x, y) (SVG 2, 5.6), then the referenced element, or a <symbol>'s
  /// children through its viewBox (SVG 1.1, 5.5 and 7.8).
  void use(const pugi::xml_node& n, Affine m, std::size_t transforms, std::size_t owner, const Hiding& hiding,
           std::size_t depth) {
    const Where where = doc_.where(n);
    const std::string href = href_of(n);
    if (href.empty()) where.fail("has no href; expected href=\"#id\" of the element it clones");
    if (href.front() != '#')
      where.fail("references \"" + href + "\", outside this file; rollkin follows references within the file "
                 "(href=\"#id\")");
    const auto target = doc_.ids.find(href.substr(1));
    if (target == doc_.ids.end()) where.fail("references \"" + href + "\", which is not in the file");
    if (target->second.size() > 1)
      where.fail("references \"" + href + "\", an id used by " + std::to_string(target->second.size()) +
                 " elements (ids must be unique); rename the others in the editor");
    if (std::find(uses_.begin(), uses_.end(), n) != uses_.end()) {
      std::string cycle;
      for (const pugi::xml_node& u : uses_) cycle += doc_.location(u) + " -> ";
      where.fail("is part of a <use> cycle (" + cycle + doc_.location(n) + "): the clone contains itself; break "
                 "the cycle in the editor");
    }
    if (uses_.size() >= kMaxUseDepth)
      where.fail("nests <use> clones more than " + std::to_string(kMaxUseDepth) + " deep; unlink some clones "
                 "in the editor (Edit > Clone > Unlink Clone)");
    m = m * Affine::translate(user_length(n, "x", where, 0.0), user_length(n, "y", where, 0.0));
    const pugi::xml_node t = target->second.front();
    const std::string saved_via = via_;
    if (uses_.empty()) use_owner_ = owner;
    via_ = " (drawn by " + doc_.location(n) + ")" + via_;
    uses_.push_back(n);
    if (local_name(t) == element::symbol) {
      m = m * own_transform(t, doc_, transforms) * symbol_viewbox(n, t);
      if (const std::string e = unexpanded_entity(doc_, t); !e.empty()) doc_.where(t).fail(e);
      // display does not apply to a <symbol> (SVG 1.1, 5.5: drawn through a <use> whatever its display); its
      // visibility is inherited by its content
      OwnRendering symbol = own_rendering(t, doc_);
      symbol.display_none = false;
      const Hiding inner = hiding.below(symbol, Hiding::inside);
      for (const pugi::xml_node c : t.children())
        if (c.type() == pugi::node_element) element(c, m, transforms, owner, inner, false, depth + 1);
    } else {
      element(t, m, transforms, owner, hiding, false, depth + 1);
    }
    uses_.pop_back();
    via_ = saved_via;
  }

  /// A <symbol>'s viewBox mapped onto the <use>'s width and height (SVG 1.1, 5.6 and 7.8); identity without a
  /// viewBox (the symbol's content is then drawn in the <use>'s coordinates).
  Affine symbol_viewbox(const pugi::xml_node& use, const pugi::xml_node& symbol) const {
    const Where where = doc_.where(symbol);
    for (const char* a : {"x", "y"})
      if (symbol.attribute(a) && user_length(symbol, a, where, 0.0) != 0)
        where.fail(std::string("has ") + a + "=\"" + symbol.attribute(a).value() + "\", which rollkin does not "
                   "apply; position the symbol with the <use>'s x and y instead");
    const pugi::xml_attribute vb_attr = symbol.attribute("viewBox");
    if (!vb_attr) return Affine{};
    const std::vector<double> vb = number_list(vb_attr.value(), "viewBox", where);
    if (vb.size() != 4 || !(vb[2] > 0) || !(vb[3] > 0))
      where.fail(std::string("viewBox=\"") + vb_attr.value() +
                 "\" is not \"min-x min-y width height\" with a positive width and height");
    const Where use_where = doc_.where(use);
    double size[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const char* name = k == 0 ? "width" : "height";
      const pugi::xml_node from = use.attribute(name) ? use : symbol;
      if (!from.attribute(name))
        use_where.fail(std::string("clones the <symbol> ") + doc_.location(symbol) + ", which has a viewBox, "
                       "without " + name + ": the symbol would fill 100% of the viewport, which rollkin does not "
                       "resolve; give the <use> width and height in user units");
      size[k] = user_length(from, name, from == use ? use_where : where, std::nullopt);
      if (!(size[k] > 0)) (from == use ? use_where : where).fail(std::string(name) + " must be positive");
    }
    return viewbox_map(vb, size[0], size[1], symbol.attribute("preserveAspectRatio").value(), where);
  }

  const Document& doc_;
  std::vector<pugi::xml_node> uses_;        // the <use> elements being expanded, outermost first
  std::size_t use_owner_ = Owners::none;    // the outermost <use> being expanded, in set.owners
  std::string via_;
};

/// The <use> elements that reference `n` or one of its ancestors, for the message about an element that is
/// drawn only through them.
std::string uses_of(const Document& doc, const pugi::xml_node& n) {
  std::vector<std::string> hrefs;
  for (pugi::xml_node a = n; a && a != doc.root; a = a.parent())
    if (a.attribute("id")) hrefs.push_back("#" + std::string(a.attribute("id").value()));
  std::string list;
  std::size_t count = 0;
  for_each_element(doc.root, [&](const pugi::xml_node& u) {
    if (local_name(u) != element::use || std::find(hrefs.begin(), hrefs.end(), href_of(u)) == hrefs.end()) return;
    if (++count <= 10) list += (list.empty() ? "" : ", ") + doc.location(u);
  });
  return list.empty() ? "no <use> references it" : "select the clone by its <use>'s id instead: " + list;
}

}  // namespace

/// The shapes the element `selected` draws where it stands in the document: its ancestors' transforms
/// (innermost first, SVG 1.1, 7.5) applied, checked to draw it at all.
DrawnSet drawn_by(const Document& doc, const pugi::xml_node& selected) {
  Affine m;
  std::size_t transforms = 0;
  std::vector<pugi::xml_node> ancestors;
  for (pugi::xml_node child = selected, n = selected.parent(); n && n != doc.root; child = n, n = n.parent()) {
    const std::string kind = local_name(n);
    if (is_referenced_only(kind))
      doc.where(selected).fail("the element is inside <" + kind + "> (" + doc.location(n) + "): it is drawn only "
                               "where a <use> clones it; " + uses_of(doc, selected));
    if (kind == element::switch_ && switch_choice(n, doc) != child)
      doc.where(selected).fail("the element is not drawn: the <switch> (" + doc.location(n) + ") draws only its "
                               "first child that renders, which is " +
                               (switch_choice(n, doc) ? doc.location(switch_choice(n, doc)) : std::string("none")) +
                               "; select an element of that child or take this one out of the <switch>");
    if (kind == element::svg)
      doc.where(selected).fail("the element is inside a nested <svg> viewport (" + doc.location(n) +
                               "), which rollkin does not apply; ungroup it in the editor");
    if (kind == element::use || is_shape(kind)) return {};  // content of a shape or of a <use> is not drawn
    try {
      m = own_transform(n, doc, transforms) * m;
    } catch (const InputError& e) {
      throw InputError(doc.file, doc.location(selected) + " (its ancestor " + doc.location(n) + ")", e.message());
    }
    ancestors.push_back(n);
  }
  if (doc.root.attribute("transform")) own_transform(doc.root, doc, transforms);
  DrawnCollector collect(doc);
  std::size_t owner = Owners::none;
  for (auto a = ancestors.rbegin(); a != ancestors.rend(); ++a) owner = collect.set.owners.add(*a, owner);
  collect.element(selected, m, transforms, owner, Hiding{}, true);  // named by its id: drawn whatever hides it
  return std::move(collect.set);
}

/// Everything the document draws.
DrawnSet drawn_in_document(const Document& doc) {
  std::size_t transforms = 0;
  own_transform(doc.root, doc, transforms);
  DrawnCollector collect(doc);
  if (const std::string e = unexpanded_entity(doc, doc.root); !e.empty()) doc.where(doc.root).fail(e);
  for (const pugi::xml_node c : doc.root.children())
    if (c.type() == pugi::node_element) collect.element(c, Affine{}, 0, Owners::none, Hiding{});
  return std::move(collect.set);
}

/// The document's <style> sheets must not set CSS transforms (they could apply to any element).
void check_style_sheets(const Document& doc) {
  for_each_element(doc.root, [&](const pugi::xml_node& n) {
    if (local_name(n) != element::style) return;
    if (!css_transform_property(n.text().get()).empty())
      doc.where(n).fail("the document's <style> sheet sets a CSS transform (" + css_transform_property(n.text().get()) +
                        "), which rollkin does not apply; use transform attributes instead");
    if (const std::string p = css_rendering_property(n.text().get()); !p.empty())
      doc.where(n).fail("the document's <style> sheet sets \"" + p + "\", which rollkin does not apply (it would hide or "
                        "show elements by selectors rollkin does not match); set display or visibility on the elements "
                        "instead (attribute or style)");
  });
}

}  // namespace rollkin::io::svg_detail
