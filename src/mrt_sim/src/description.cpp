// Sensor mounts from the URDF of a robot's base (description.h).
#include "mrt_sim/description.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <Eigen/Geometry>
#include <urdf_parser/urdf_parser.h>

namespace mrt::sim {

std::string default_description_dir() {
#ifdef MRT_DESCRIPTION_URDF_DIR
  return MRT_DESCRIPTION_URDF_DIR;
#else
  return "";
#endif
}

namespace {

std::optional<LinkMount> mount_in(const urdf::ModelInterface& model, const std::string& link) {
  urdf::LinkConstSharedPtr l = model.getLink(link);
  if (!l) return std::nullopt;
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int depth = 0; l && l->name != "base_link"; ++depth) {
    if (!l->parent_joint || depth > 64) return std::nullopt;
    const urdf::Pose& p = l->parent_joint->parent_to_joint_origin_transform;
    Eigen::Isometry3d j = Eigen::Isometry3d::Identity();
    j.translate(Eigen::Vector3d(p.position.x, p.position.y, p.position.z));
    j.rotate(Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z));
    t = j * t;
    l = model.getLink(l->parent_joint->parent_link_name);
  }
  if (!l) return std::nullopt;
  LinkMount m;
  m.position = t.translation();
  const Eigen::Vector3d x = t.linear() * Eigen::Vector3d::UnitX();
  m.yaw = std::atan2(x.y(), x.x());
  return m;
}

}  // namespace

std::optional<LinkMount> link_mount(const std::string& urdf_xml, const std::string& link) {
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  if (!model) throw std::runtime_error("cannot parse the URDF");
  return mount_in(*model, link);
}

std::optional<DescriptionMounts> read_description(const std::string& dir, const std::string& base) {
  if (dir.empty()) return std::nullopt;
  const std::string path = dir + "/" + base + ".urdf";
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(ss.str());
  if (!model) throw std::runtime_error(path + ": cannot parse the URDF");
  DescriptionMounts d;
  d.omni_mirror = mount_in(*model, "omni_mirror");
  d.mouse_left = mount_in(*model, "mouse_left");
  d.mouse_right = mount_in(*model, "mouse_right");
  for (int i = 0; i < 360; ++i) {
    const auto m = mount_in(*model, "sonar_" + std::to_string(i));
    if (!m) break;
    d.sonars.push_back(*m);
  }
  return d;
}

}  // namespace mrt::sim
