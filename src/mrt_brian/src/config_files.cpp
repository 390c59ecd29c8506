#include "mrt_brian/config_files.h"

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <utility>

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

const std::string& ConfigFiles::first(Slot s) const {
  switch (s) {
    case Slot::kCtof: return ctof;
    case Slot::kShapeCtof: return shape_ctof;
    case Slot::kPredicates: return predicates;
    case Slot::kPredicateActions: return predicate_actions;
    case Slot::kCando: return cando;
    case Slot::kBehaviors: return behaviors;
    case Slot::kWant: return want;
    case Slot::kSFtoc: return s_ftoc;
    case Slot::kSShape: return s_shape;
  }
  return ctof;
}

std::string& ConfigFiles::first(Slot s) { return const_cast<std::string&>(std::as_const(*this).first(s)); }

std::vector<std::string> ConfigFiles::all(Slot s) const {
  std::vector<std::string> out;
  if (!first(s).empty()) out.push_back(first(s));
  const auto& m = more[static_cast<std::size_t>(s)];
  out.insert(out.end(), m.begin(), m.end());
  return out;
}

ConfigFiles ConfigFiles::from_list_file(const std::string& path, common::PackageFinder packages) {
  const std::string text = read_text_file(path);
  ConfigFiles f;
  f.packages = std::move(packages);
  f.base_dir = fs::path(path).parent_path().string();
  if (f.base_dir.empty()) f.base_dir = ".";
  std::vector<std::vector<std::string>> slots;  // one entry a non-comment line
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '#') continue;
    if (slots.size() == kSlotCount)
      throw ParseError(path, lineno, static_cast<int>(b) + 1, "expected nine file names, got more");
    std::istringstream words(line);
    std::vector<std::string> names;
    for (std::string w; words >> w && w[0] != '#';) {  // '#': a comment to the end
      try {
        names.push_back(f.resolve(w));
      } catch (const std::invalid_argument& e) {
        throw ParseError(path, lineno, static_cast<int>(line.find(w)) + 1, e.what());
      }
    }
    if (!names.empty()) slots.push_back(std::move(names));  // (only other blanks: an empty line)
  }
  // The manual's constructor: eight, no predicate actions.
  if (slots.size() == kSlotCount - 1) slots.insert(slots.begin() + 3, std::vector<std::string>{""});
  if (slots.size() != kSlotCount)
    throw ParseError(path, lineno, 0, "expected nine file names (ctof, shape_ctof, Predicate, PredicateActions, "
                                      "Cando, behaviour list, want, s_ftoc, s_shape), got " + std::to_string(slots.size()));
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    f.first(static_cast<Slot>(i)) = slots[i].front();
    f.more[i].assign(slots[i].begin() + 1, slots[i].end());
  }
  return f;
}

ConfigFiles ConfigFiles::locate(const std::string& path, common::PackageFinder packages) {
  // error_code overloads: a path that cannot even be examined (a
  // non-searchable directory on the way, a name too long) is a ParseError
  // naming the path, never a std::filesystem::filesystem_error.
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw ParseError(path, 0, 0, "cannot access: " + ec.message());
  if (fs::is_directory(st)) {
    ConfigFiles f = from_directory(path);
    f.packages = std::move(packages);
    return f;
  }
  return from_list_file(path, std::move(packages));
}

std::string ConfigFiles::resolve(const std::string& p) const {
  if (common::is_package_url(p)) return common::resolve_package_url(p, packages);
  if (p.empty() || fs::path(p).is_absolute()) return p;
  // Not lexically normalised: "a/link/../b" must go through the symlink.
  return (fs::path(base_dir) / p).string();
}

namespace {
// The definitions of every file of a slot, in order.
template <typename T, typename F>
std::vector<T> parse_slot(const ConfigFiles& files, Slot slot, F parse_fn) {
  std::vector<T> out;
  for (const std::string& file : files.all(slot)) {
    std::vector<T> defs = parse_fn(read_text_file(file), file);
    out.insert(out.end(), std::make_move_iterator(defs.begin()), std::make_move_iterator(defs.end()));
  }
  return out;
}
}  // namespace

ParsedConfig ParsedConfig::load(const ConfigFiles& files, const std::vector<std::string>& custom_extensions) {
  ParsedConfig c;
  c.files = files;
  c.assocs = parse_slot<AssociationDef>(files, Slot::kCtof, parse_associations);
  c.shapes = parse_slot<ShapeDef>(files, Slot::kShapeCtof, parse_shapes);
  c.predicates = parse_slot<DefinitionDef>(files, Slot::kPredicates, parse_definitions);
  c.predicate_actions = parse_slot<DefinitionDef>(files, Slot::kPredicateActions, parse_definitions);
  c.cando = parse_slot<DefinitionDef>(files, Slot::kCando, parse_definitions);
  c.behaviors = parse_slot<BehaviorDef>(files, Slot::kBehaviors, parse_behavior_list);
  c.want = parse_slot<DefinitionDef>(files, Slot::kWant, parse_definitions);
  c.out_assocs = parse_slot<AssociationDef>(files, Slot::kSFtoc, parse_associations);
  c.out_shapes = parse_slot<ShapeDef>(files, Slot::kSShape, parse_shapes);
  for (const auto& b : c.behaviors) {
    std::string path;
    try {
      path = files.resolve(b.path);
    } catch (const std::invalid_argument& e) {
      throw ParseError(b.file, b.line, b.column, e.what());
    }
    std::string text;
    try {
      text = read_text_file(path);
    } catch (const ParseError&) {
      throw ParseError(b.file, b.line, b.column, "cannot open behaviour file '" + path + "'");
    }
    c.behavior_files.push_back(path);
    const std::string ext = fs::path(path).extension().string();
    const bool custom = std::find(custom_extensions.begin(), custom_extensions.end(), ext) != custom_extensions.end();
    c.rules.push_back(custom ? std::vector<RuleDef>{} : parse_rules(text, path));
  }
  return c;
}

}  // namespace mrt::brian
