#pragma once
// The URDF reader's parts: one UrdfReader reads one document — its links, joints and tree
// (urdf_file.cpp), and its links' geometry: the shapes and meshes drawn, the mass of a link
// without <inertial>, and where a mesh's file name leads (urdf_geometry.cpp).

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tinyxml2.h>

#include "momenta/io/model_file.hpp"
#include "momenta/math/types.hpp"

namespace momenta::io::detail {

using tinyxml2::XMLElement;

/// Where a URDF mesh's file name leads: `package://NAME/path` to the folder NAME found on
/// `package_path` (a folder named NAME, or holding one directly or a few levels down beside a
/// package.xml), `file:///absolute`, a plain path relative to `base_dir`. Throws InvalidArgument
/// saying why not (an unknown scheme, a package not found with the folders searched).
std::filesystem::path resolve_mesh_uri(std::string_view uri, const std::filesystem::path& base_dir,
                                       const std::vector<std::filesystem::path>& package_path);

/// The folders a `package://` URI is looked for in: `given`, then ROS_PACKAGE_PATH's entries.
std::vector<std::filesystem::path> package_search_path(
    const std::vector<std::filesystem::path>& given);

class UrdfReader {
 public:
  UrdfReader(const tinyxml2::XMLDocument& document, std::string file,
             const ModelFileOptions& options, std::filesystem::path base_dir);

  ModelFile read();

 private:
  struct Link {
    const XMLElement* element;
    inertia::MassProperties mass_properties;
    bool has_inertial = false;
    std::vector<PartSummary> drawn;  // what the report draws: the visuals, else the collisions
  };
  struct JointEntry {
    const XMLElement* element;
    model::Joint joint;
    std::string mimic;  // the mimicked joint's name, or empty
    double multiplier = 1.0, offset = 0.0;
    const XMLElement* mimic_element = nullptr;
  };

  [[noreturn]] void fail(const XMLElement* at, const std::string& message) const;
  void note(const XMLElement* at, const std::string& message);

  std::string name_of(const XMLElement* e, const char* what) const;
  double number(const XMLElement* e, const char* attribute, std::optional<double> fallback) const;
  Vec3 vector3(const XMLElement* e, const char* attribute, const Vec3& fallback) const;
  Transform origin(const XMLElement* parent) const;
  std::string link_reference(const XMLElement* joint, const char* which) const;

  void read_link(const XMLElement* e);
  void read_joint(const XMLElement* e);
  void read_limit(const XMLElement* limit, std::string_view type, JointEntry& entry);
  void note_ignored_children(const XMLElement* e, const std::string& owner,
                             std::initializer_list<std::string_view> used);
  model::Model build(const model::ModelBuilder& builder, const std::vector<ItemLocation>& items);

  // --- geometry (urdf_geometry.cpp) -----------------------------------------------------------
  /// The <geometry> of one <visual> or <collision> of link `owner`, as a part placed in the link
  /// frame by the element's <origin>; its mass properties filled with `density` when given. A
  /// mesh only drawn (no `density`) that cannot be found or read is a note, and no part.
  std::optional<PartSummary> geometry_part(const XMLElement* e, const std::string& owner,
                                           std::size_t index, std::optional<double> density);
  /// The mesh file `uri` names (<mesh filename>), scaled per axis, read once per file and scale.
  /// One that cannot be found or read fails at `at` when `weighed`, else is noted there as not
  /// drawn (null): most URDFs arrive without their mesh packages, and none is needed for the
  /// dynamics unless a link is weighed from its geometry.
  std::shared_ptr<const inertia::TriangleMesh> mesh(const XMLElement* at, const std::string& uri,
                                                    const Vec3& scale, bool weighed);
  /// Link `link`'s drawn parts and, where it has no <inertial> and a density is given, its mass
  /// properties from its collision geometry (else its visual geometry).
  void read_geometry(const XMLElement* e, Link& link, const std::string& owner);

  const tinyxml2::XMLDocument& document_;
  std::string file_;
  ModelFileOptions options_;
  std::filesystem::path base_dir_;
  std::vector<std::filesystem::path> package_path_;
  std::map<std::string, std::shared_ptr<const inertia::TriangleMesh>> meshes_;
  std::map<std::string, Link> links_;
  std::vector<std::string> link_order_;
  std::map<std::string, JointEntry> joints_;
  std::vector<std::string> joint_order_;
  std::vector<std::pair<int, std::string>> notes_;  // line, text
};

}  // namespace momenta::io::detail
