#define BOOST_TEST_MODULE io_json_document
#include <boost/test/unit_test.hpp>

#include "test_support.hpp"

#include "rollkin/io/json/document.hpp"

#include <string>

using rollkin::io::InputError;
using rollkin::io::kMaxJsonDepth;
using rollkin::io::parse_json_document;
using json = nlohmann::ordered_json;

namespace {

using namespace rollkin::testing;

/// The InputError for `text`, which must throw one.
InputError error_of(const std::string& text, const std::string& file = "scene.json") {
  try {
    parse_json_document(text, file);
  } catch (const InputError& e) {
    return e;
  }
  BOOST_FAIL("no InputError for the document");
  throw;
}

/// `{"description": [[[...1...]]]}` with `levels` nested arrays (or objects {"a": ...}) inside the key.
std::string nested(std::size_t levels, bool objects) {
  std::string text = "{\"description\": ";
  text.reserve(2 * levels * (objects ? 6 : 1) + 32);
  for (std::size_t i = 0; i < levels; ++i) text += objects ? "{\"a\": " : "[";
  text += "1";
  for (std::size_t i = 0; i < levels; ++i) text += objects ? "}" : "]";
  return text + "}";
}

}  // namespace

BOOST_AUTO_TEST_CASE(valid_documents_equal_nlohmanns_own_parse) {
  // Independent truth: nlohmann's DOM parser on the same text (values, types, key order).
  const std::string text =
      "{\"units\": {\"angle\": \"deg\"}, \"links\": [{\"name\": \"ground\", \"ground\": true},\n"
      " {\"name\": \"crank\", \"contours\": [{\"type\": \"circle\", \"radius\": 1.5e-3, \"n\": -7, \"u\": 18446744073709551615}]}],\n"
      " \"z\": null, \"b\": false, \"s\": \"\\u00e9\\n\", \"e\": [], \"o\": {}, \"deep\": [[[{\"k\": [1, [2]]}]]]}";
  const json mine = parse_json_document(text, "x.json");
  const json theirs = json::parse(text);
  BOOST_TEST(mine == theirs);
  BOOST_TEST(mine.dump() == theirs.dump());
  BOOST_TEST(parse_json_document("[1, 2]", "x").dump() == "[1,2]");
  BOOST_TEST(parse_json_document(" 3 ", "x").get<int>() == 3);
}

BOOST_AUTO_TEST_CASE(depth_up_to_the_bound_is_accepted) {
  // kMaxJsonDepth levels in all: the top-level object plus kMaxJsonDepth - 1 arrays.
  const json j = parse_json_document(nested(kMaxJsonDepth - 1, false), "x.json");
  const json* v = &j["description"];
  std::size_t depth = 1;
  while (v->is_array()) {
    v = &(*v)[0];
    ++depth;
  }
  BOOST_TEST(depth == kMaxJsonDepth);
  BOOST_TEST(v->get<int>() == 1);
}

BOOST_AUTO_TEST_CASE(deeper_nesting_is_a_located_error_at_any_depth) {
  // 10^6 levels crashed (stack overflow), 10^5 were accepted silently.
  for (std::size_t levels : {std::size_t(kMaxJsonDepth), std::size_t(1000), std::size_t(100000), std::size_t(1000000)})
    for (bool objects : {false, true}) {
      const InputError e = error_of(nested(levels, objects), "deep.json");
      BOOST_TEST_CONTEXT(levels << (objects ? " objects" : " arrays")) {
        BOOST_TEST(e.file() == "deep.json");
        // The opener of level kMaxJsonDepth + 1 (the object is level 1): column 17 + 6 k or 17 + k.
        const std::size_t column = 16 + (kMaxJsonDepth - 1) * (objects ? 6 : 1) + 1;
        BOOST_TEST(e.location() == "1:" + std::to_string(column));
        BOOST_TEST(contains(e.message(), "nested deeper than 256 levels"));
        BOOST_TEST(contains(e.message(), objects ? "at description.a.a.a" : "at description[0][0][0]"));
        BOOST_TEST(std::string(e.what()).size() < 400u);
      }
    }
}

BOOST_AUTO_TEST_CASE(duplicate_keys_name_line_column_and_full_path) {
  const std::string text =
      "{\"links\": [\n"
      "  {\"name\": \"ground\"},\n"
      "  {\"name\": \"b\", \"contours\": [{\"type\": \"circle\", \"radius\": 1,\n"
      "                                \"radius\": 2}]}\n"
      "]}\n";
  const InputError e = error_of(text);
  BOOST_TEST(e.location() == "4:40");  // the closing quote of the second "radius"
  BOOST_TEST(contains(e.message(), "duplicate key \"radius\" at links[1].contours[0].radius"));
  // The same key in different objects is fine.
  BOOST_CHECK_NO_THROW(parse_json_document("[{\"a\": 1}, {\"a\": 2}, {\"b\": {\"a\": 3}}]", "x"));
  BOOST_TEST(error_of("{\"a\": {\"b\": [0, {\"c\": 1, \"c\": 1}]}}").message().find("at a.b[1].c") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(out_of_range_numbers_name_line_column_and_path) {
  const InputError e = error_of("{\"links\": [{\"name\": \"a\"},\n {\"radius\": 1e400}]}", "big.json");
  BOOST_TEST(e.file() == "big.json");
  BOOST_TEST(e.location() == "2:17");  // the number's last character
  BOOST_TEST(contains(e.message(), "number 1e400 at links[1].radius is out of the range of a double"));
  BOOST_TEST(contains(error_of("{\"x\": [0, -1e999]}").message(), "number -1e999 at x[1]"));
  const std::string huge_integer = "1" + std::string(400, '0');
  BOOST_TEST(contains(error_of("{\"x\": " + huge_integer + "}").message(), "at x is out of the range"));
  BOOST_TEST(contains(error_of("{\"x\": " + huge_integer + "}").message(), "..."));  // the number is cut
  // Large but finite numbers are fine.
  BOOST_TEST(parse_json_document("[1e308, -1.7e308, 1e-400]", "x")[1].get<double>() == -1.7e308);
}

BOOST_AUTO_TEST_CASE(malformed_json_names_line_column_and_path) {
  const InputError e = error_of("{\n  \"links\": [\n    {\"name\": \"a\" \"ground\": true}\n  ]\n}\n");
  BOOST_TEST(e.location() == "3:25");  // the closing quote of the unexpected string "ground"
  BOOST_TEST(contains(e.message(), "malformed JSON"));
  BOOST_TEST(contains(e.message(), "(in links[0].name)"));
  BOOST_TEST(contains(error_of("").message(), "malformed JSON"));
  BOOST_TEST(contains(error_of("{} {}").message(), "malformed JSON"));
  // An unterminated string of 10^5 characters is quoted in a message of readable length.
  const InputError longer = error_of("{\"a\": \"" + std::string(100000, 'x'));
  BOOST_TEST(std::string(longer.what()).size() < 400u);
}

// ---- set_at_path: overrides by JSON path (the Python module's Scene.modified) -----------------------------

namespace {

/// The InputError of set_at_path(doc, path, value), which must throw one.
InputError override_error(json doc, const std::string& path, const json& value = 1) {
  try {
    rollkin::io::set_at_path(doc, path, value, "scene.json");
  } catch (const InputError& e) {
    return e;
  }
  BOOST_FAIL("no InputError for the path " + path);
  throw;
}

const char* const kSmallScene = R"({"links": [{"name": "g"}, {"name": "c", "contours": [{"name": "p", "a": 0.5}]}],
                                    "sweep": {"from": 0, "to": 1}})";

}  // namespace

BOOST_AUTO_TEST_CASE(set_at_path_replaces_the_value_at_keys_and_indices) {
  json doc = parse_json_document(kSmallScene, "scene.json");
  rollkin::io::set_at_path(doc, "links[1].contours[0].a", 0.75, "scene.json");
  BOOST_TEST(doc["links"][1]["contours"][0]["a"].get<double>() == 0.75);
  rollkin::io::set_at_path(doc, "sweep.to", json::array({1, 2}), "scene.json");
  BOOST_TEST(doc["sweep"]["to"] == json::array({1, 2}));
  rollkin::io::set_at_path(doc, "sweep.to[1]", "x", "scene.json");
  BOOST_TEST(doc["sweep"]["to"][1] == "x");
  // The last step may add a key (the scene reader then checks whether it is allowed); nothing else changed.
  rollkin::io::set_at_path(doc, "links[0].ground", true, "scene.json");
  BOOST_TEST(doc["links"][0]["ground"] == true);
  BOOST_TEST(doc["links"][0].size() == 2u);
  BOOST_TEST(doc["links"][1]["name"] == "c");
  rollkin::io::set_at_path(doc, "links", json::array(), "scene.json");
  BOOST_TEST(doc["links"].empty());
}

BOOST_AUTO_TEST_CASE(set_at_path_errors_name_the_path_and_what_is_there) {
  const json doc = parse_json_document(kSmallScene, "scene.json");
  const InputError beyond = override_error(doc, "links[2].name");
  BOOST_TEST(beyond.file() == "scene.json");
  BOOST_TEST(beyond.location() == "links[2].name");
  BOOST_TEST(beyond.message() == "no element [2]: links has 2 element(s)");
  const InputError missing = override_error(doc, "links[1].contour[0].a");
  BOOST_TEST(missing.message() == "no key \"contour\" in links[1]; its keys are \"name\", \"contours\"");
  BOOST_TEST(override_error(doc, "links[1].name[0]").message() == "links[1].name is a string, not an array; there is no [0]");
  BOOST_TEST(override_error(doc, "sweep[0]").message() == "sweep is an object, not an array; there is no [0]");
  BOOST_TEST(override_error(doc, "links.name").message() == "links is an array, not an object; there is no key \"name\"");
  for (const char* bad : {"", ".", "links.", ".links", "links..a", "links[", "links[]", "links[x]", "links[-1]", "links]",
                          "links[1]name", "links[1].", "a]b", "links[99999999999999999999]"}) {
    const InputError e = override_error(doc, bad);
    BOOST_TEST(e.location() == bad);
    BOOST_TEST(contains(e.message(), "not a JSON path"), bad);
  }
}
