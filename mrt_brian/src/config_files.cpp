#include "mrt_brian/config_files.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "mrt_brian/behavior_list_parser.h"
#include "mrt_brian/lexer.h"
#include "mrt_brian/predicate_parser.h"
#include "mrt_brian/rule_parser.h"
#include "mrt_brian/shape_parser.h"
#include "mrt_common/parse_error.h"

namespace fs = std::filesystem;

namespace mrt::brian {

using mrt::common::ParseError;

namespace {
std::string first_existing(const fs::path& dir, std::initializer_list<const char*> names, bool required) {
  std::error_code ec;  // an unreadable entry counts as missing; reading it reports why
  for (const char* n : names)
    if (fs::is_regular_file(dir / n, ec)) return (dir / n).string();
  if (!required) return "";
  return (dir / *names.begin()).string();  // reported as "cannot open file" when read
}
}  // namespace

ConfigFiles ConfigFiles::from_directory(const std::string& dir) {
  const fs::path d(dir);
  std::error_code ec;
  if (!fs::is_directory(d, ec))
    throw ParseError(dir, 0, 0, ec ? "cannot access directory: " + ec.message() : std::string("not a directory"));
  ConfigFiles f;
  f.base_dir = dir;
  f.ctof = first_existing(d, {"ctof.txt"}, true);
  f.shape_ctof = first_existing(d, {"shape_ctof.txt"}, true);
  f.predicates = first_existing(d, {"Predicate.ini"}, true);
  f.predicate_actions = first_existing(d, {"PredicateActions.ini"}, false);
  f.cando = first_existing(d, {"Cando.ini"}, true);
  f.behaviors = first_existing(d, {"behavior.txt", "behaviour.txt"}, true);
  f.want = first_existing(d, {"want.txt", "Want.ini"}, true);
  f.s_ftoc = first_existing(d, {"s_ftoc.txt"}, true);
  f.s_shape = first_existing(d, {"s_shape.txt"}, true);
  return f;
}

ConfigFiles ConfigFiles::from_list_file(const std::string& path) {
  const std::string text = read_text_file(path);
  ConfigFiles f;
  f.base_dir = fs::path(path).parent_path().string();
  if (f.base_dir.empty()) f.base_dir = ".";
  std::vector<std::string> names;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '#') continue;
    const auto e = line.find_last_not_of(" \t\r");
    const std::string name = line.substr(b, e - b + 1);
    if (name.find_first_of(" \t") != std::string::npos)
      throw ParseError(path, lineno, static_cast<int>(b) + 1, "expected one file name a line, got '" + name + "'");
    if (names.size() == 9) throw ParseError(path, lineno, static_cast<int>(b) + 1, "expected nine file names, got more");
    names.push_back(f.resolve(name));
  }
  if (names.size() == 8) names.insert(names.begin() + 3, "");  // the manual's constructor: no predicate actions
  if (names.size() != 9)
    throw ParseError(path, lineno, 0, "expected nine file names (ctof, shape_ctof, Predicate, PredicateActions, "
                                      "Cando, behaviour list, want, s_ftoc, s_shape), got " + std::to_string(names.size()));
  f.ctof = names[0];
  f.shape_ctof = names[1];
  f.predicates = names[2];
  f.predicate_actions = names[3];
  f.cando = names[4];
  f.behaviors = names[5];
  f.want = names[6];
  f.s_ftoc = names[7];
  f.s_shape = names[8];
  return f;
}

ConfigFiles ConfigFiles::locate(const std::string& path) {
  // error_code overloads: a path that cannot even be examined (a
  // non-searchable directory on the way, a name too long) is a ParseError
  // naming the path, never a std::filesystem::filesystem_error.
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw ParseError(path, 0, 0, "cannot access: " + ec.message());
  if (fs::is_directory(st)) return from_directory(path);
  return from_list_file(path);
}

std::string ConfigFiles::resolve(const std::string& p) const {
  if (p.empty() || fs::path(p).is_absolute()) return p;
  // Not lexically normalised: "a/link/../b" must go through the symlink.
  return (fs::path(base_dir) / p).string();
}

ParsedConfig ParsedConfig::load(const ConfigFiles& files, const std::vector<std::string>& custom_extensions) {
  ParsedConfig c;
  c.files = files;
  c.assocs = parse_associations(read_text_file(files.ctof), files.ctof);
  c.shapes = parse_shapes(read_text_file(files.shape_ctof), files.shape_ctof);
  c.predicates = parse_definitions(read_text_file(files.predicates), files.predicates);
  if (!files.predicate_actions.empty())
    c.predicate_actions = parse_definitions(read_text_file(files.predicate_actions), files.predicate_actions);
  c.cando = parse_definitions(read_text_file(files.cando), files.cando);
  c.behaviors = parse_behavior_list(read_text_file(files.behaviors), files.behaviors);
  c.want = parse_definitions(read_text_file(files.want), files.want);
  c.out_assocs = parse_associations(read_text_file(files.s_ftoc), files.s_ftoc);
  c.out_shapes = parse_shapes(read_text_file(files.s_shape), files.s_shape);
  for (const auto& b : c.behaviors) {
    const std::string path = files.resolve(b.path);
    std::string text;
    try {
      text = read_text_file(path);
    } catch (const ParseError&) {
      throw ParseError(files.behaviors, b.line, b.column, "cannot open behaviour file '" + path + "'");
    }
    c.behavior_files.push_back(path);
    const std::string ext = fs::path(path).extension().string();
    const bool custom = std::find(custom_extensions.begin(), custom_extensions.end(), ext) != custom_extensions.end();
    c.rules.push_back(custom ? std::vector<RuleDef>{} : parse_rules(text, path));
  }
  return c;
}

}  // namespace mrt::brian
