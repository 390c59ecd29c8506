// ROS package paths without ROS: where a package lives, found the way
// rospack finds it (the directories of ROS_PACKAGE_PATH, each a package or
// holding packages below it), and `package://<package>/<path>` resource
// paths (the ROS resource-URL form of URDF meshes and resource_retriever)
// resolved through it, so that a configuration file can name another
// package's file in a source tree, a devel space and an install space
// alike. ROS-free, header-only.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace mrt::common {

/// A package name to its directory, "" when unknown.
using PackageFinder = std::function<std::string(const std::string& name)>;

namespace detail {

/// The <name> of a package.xml, "" when there is none.
inline std::string package_xml_name(const std::filesystem::path& dir) {
  std::ifstream in(dir / "package.xml");
  if (!in) return "";
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  const auto a = s.find("<name>");
  const auto b = a == std::string::npos ? a : s.find("</name>", a);
  if (b == std::string::npos) return "";
  std::string n = s.substr(a + 6, b - a - 6);
  const auto first = n.find_first_not_of(" \t\r\n");
  const auto last = n.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : n.substr(first, last - first + 1);
}

/// rospack's crawl below `dir`: a directory with a package.xml is a package
/// (not looked into), one with a CATKIN_IGNORE is skipped; at most `depth`
/// levels down.
inline std::string crawl(const std::filesystem::path& dir, const std::string& name, int depth) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (depth < 0 || fs::exists(dir / "CATKIN_IGNORE", ec)) return "";
  if (fs::is_regular_file(dir / "package.xml", ec)) return package_xml_name(dir) == name ? dir.string() : "";
  for (fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (!it->is_directory(ec) || it->path().filename().string().rfind('.', 0) == 0) continue;
    const std::string found = crawl(it->path(), name, depth - 1);
    if (!found.empty()) return found;
  }
  return "";
}

}  // namespace detail

/// The directory of package `name` on `search_path` (directories separated
/// by ':', as ROS_PACKAGE_PATH): the first root that is the package, or
/// holds it as `<root>/<name>`, else the first found by crawling the roots
/// as rospack does (at most four levels down); "" when none has it.
inline std::string find_package_dir(const std::string& name, const std::string& search_path) {
  namespace fs = std::filesystem;
  if (name.empty()) return "";
  std::vector<fs::path> roots;
  std::stringstream ss(search_path);
  for (std::string r; std::getline(ss, r, ':');)
    if (!r.empty()) roots.emplace_back(r);
  std::error_code ec;
  for (const fs::path& r : roots) {
    if (detail::package_xml_name(r) == name) return r.string();
    if (fs::is_regular_file(r / name / "package.xml", ec) && detail::package_xml_name(r / name) == name)
      return (r / name).string();
  }
  for (const fs::path& r : roots) {
    const std::string found = detail::crawl(r, name, 4);
    if (!found.empty()) return found;
  }
  return "";
}

/// The directory of package `name` on ROS_PACKAGE_PATH ("" when unset or
/// not found).
inline std::string find_package_dir(const std::string& name) {
  const char* p = std::getenv("ROS_PACKAGE_PATH");
  return p ? find_package_dir(name, p) : "";
}

/// A finder that knows `roots` (package name -> directory: what a build
/// gives a ROS-free program) and asks ROS_PACKAGE_PATH for the others.
inline PackageFinder package_finder(std::map<std::string, std::string> roots = {}) {
  return [roots = std::move(roots)](const std::string& name) {
    const auto it = roots.find(name);
    return it != roots.end() ? it->second : find_package_dir(name);
  };
}

inline constexpr const char* kPackageUrlScheme = "package://";

inline bool is_package_url(const std::string& p) { return p.rfind(kPackageUrlScheme, 0) == 0; }

/// `package://<package>/<path>` as `<the package's directory>/<path>`
/// (`find`, or ROS_PACKAGE_PATH when it is empty); any other path is
/// returned as it is. Throws std::invalid_argument naming the package when
/// it cannot be found, or the URL when it names no package.
inline std::string resolve_package_url(const std::string& p, const PackageFinder& find = {}) {
  if (!is_package_url(p)) return p;
  const std::string rest = p.substr(std::string(kPackageUrlScheme).size());
  const auto slash = rest.find('/');
  const std::string name = rest.substr(0, slash);
  if (name.empty()) throw std::invalid_argument("'" + p + "' names no package (package://<package>/<path>)");
  const std::string dir = find ? find(name) : find_package_dir(name);
  if (dir.empty())
    throw std::invalid_argument("package '" + name + "' of '" + p + "' not found (is it on ROS_PACKAGE_PATH?)");
  return slash == std::string::npos ? dir : dir + rest.substr(slash);
}

}  // namespace mrt::common
