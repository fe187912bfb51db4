#pragma once
// The MJCF reader's parts (mjcf_*.cpp): one MjcfReader reads one document — its compiler settings,
// default classes and the body tree (mjcf_file.cpp), the frames and geoms' mass properties
// (mjcf_geometry.cpp), the equality constraints and actuators (mjcf_loads.cpp), the tendons
// (mjcf_tendons.cpp), keyframes (mjcf_keyframes.cpp) and the contacts of the bodies' geoms with
// the world's planes (mjcf_contacts.cpp).

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tinyxml2.h>

#include "momenta/io/model_file.hpp"
#include "momenta/model/model_builder.hpp"

namespace momenta::io::detail {

using tinyxml2::XMLElement;

/// An attribute's text and the element that gave it (the element itself, or the <default> entry
/// it inherits from), for messages at the right line.
struct MjcfAttribute {
  const char* text = nullptr;
  const XMLElement* where = nullptr;
  explicit operator bool() const { return text != nullptr; }
};

/// An element of the body tree with the default class it takes its missing attributes from.
struct MjcfElement {
  const XMLElement* xml = nullptr;
  std::string kind;        ///< "joint", "geom", "actuator", ...: which defaults apply
  std::string class_name;  ///< the class in force ("main" at the top)
};

/// A body as read: its frame in its parent and in the world at the drawn configuration.
struct MjcfBody {
  std::string name;           ///< momenta's body name (the final body of a joint chain)
  const XMLElement* element;  ///< the <body>
  Transform X_WB;             ///< at the configuration the file draws (every q = 0)
};

/// A joint as momenta models it: which body it moves and where its frames lie.
struct MjcfJoint {
  const XMLElement* element;
  model::Joint joint;
  double ref = 0.0;  ///< rad or m: MuJoCo's qpos at momenta's q = 0 (a hinge's or slide's `ref`)
  double springref = 0.0;  ///< rad or m: MuJoCo's qpos where its spring relaxes (`springref`)
};

/// A geom as read, for the contacts (mjcf_contacts.cpp): a body's shape, or a plane of the world.
struct MjcfGeom {
  MjcfElement element;
  std::string label;         ///< for messages: "geom 'name'" or "a geom of body 'b'"
  std::string name;          ///< for contact names: the geom's name, or <body>_geom<i>
  std::string body;          ///< momenta's body (kWorldBodyName for the world's)
  std::string type;          ///< sphere, capsule, cylinder, box, ellipsoid, mesh, plane, ...
  Transform X_BG;            ///< the geom's frame in the body (in the world for the world's)
  std::vector<double> size;  ///< MuJoCo's sizes (a capsule's or cylinder's radius, half-length)
};

class MjcfReader {
 public:
  MjcfReader(const tinyxml2::XMLDocument& document, std::string_view text, std::string file,
             const std::filesystem::path& base_dir);
  ModelFile read();

  // --- messages (mjcf_file.cpp) ----------------------------------------------------------------
  [[noreturn]] void fail(const XMLElement* at, const std::string& message,
                         const char* attribute = nullptr) const;
  void note(const XMLElement* at, const std::string& message);

  // --- attributes through the default classes (mjcf_file.cpp) ---------------------------------
  MjcfAttribute attribute(const MjcfElement& e, const char* name) const;
  double number(const MjcfElement& e, const char* name, std::optional<double> fallback) const;
  /// Between `fewest` and `most` numbers; `fallback` when absent (fails when there is none).
  std::vector<double> numbers(const MjcfElement& e, const char* name, std::size_t fewest,
                              std::size_t most,
                              std::optional<std::vector<double>> fallback = std::nullopt) const;
  Vec3 vector3(const MjcfElement& e, const char* name, const Vec3& fallback) const;
  /// One of `choices` (with a did-you-mean), or `fallback` when absent.
  std::string keyword(const MjcfElement& e, const char* name,
                      std::initializer_list<std::string_view> choices,
                      std::string_view fallback) const;
  bool flag(const MjcfElement& e, const char* name, bool fallback) const;
  /// Fails at the first attribute of `xml` not in `known`, with a did-you-mean.
  void check_attributes(const XMLElement* xml, std::initializer_list<std::string_view> known) const;

  // --- frames and mass (mjcf_geometry.cpp)
  // --------------------------------------------------------
  /// The element's pose in its parent: pos and one of quat, axisangle, euler, xyaxes, zaxis.
  Transform pose(const MjcfElement& e) const;
  /// A body's mass properties from its <inertial>, or its geoms' by MuJoCo's rule; the geoms as
  /// parts to draw.
  inertia::MassProperties body_mass_properties(const XMLElement* body, const std::string& name,
                                               const std::string& class_name,
                                               std::vector<PartSummary>& parts);
  /// The <mesh> entries of an <asset> section (the others noted as not used).
  void read_assets(const XMLElement* section);

  // --- equality constraints and actuators (mjcf_loads.cpp) ------------------------------------
  void read_equality(const XMLElement* section);
  /// An equality's polycoef as (a0, a1); fails at its element where a higher power is not zero
  /// (momenta couples joints linearly).
  std::array<double, 2> linear_polycoef(const MjcfElement& e, const std::string& name) const;
  void read_actuators(const XMLElement* section);
  /// A drive on a hinge or slide: a torque (force) pair `name` of `scale` · u along its axis, u
  /// the signal `signal` — on the child, and its reaction `<name>_reaction` on the parent.
  void add_joint_drive(const model::Joint& joint, const std::string& name,
                       const std::string& signal, double scale);

  // --- tendons (mjcf_tendons.cpp) -------------------------------------------------------------
  /// The <fixed> tendons of a <tendon> section as FixedTendon force elements, each with an output
  /// `<name>_length`; the others noted.
  void read_tendons(const XMLElement* section);
  /// An <equality><tendon> as a coupler where it relates two joints (a tendon of two joints held
  /// at its length, or two tendons of one joint each, linearly); otherwise noted, and none.
  std::optional<model::JointCoupler> tendon_coupler(const XMLElement* xml, const MjcfElement& e,
                                                    const std::string& name);

  // --- contacts (mjcf_contacts.cpp) ----------------------------------------------------------
  /// The <contact> section: the bodies excluded from the world's geoms (<exclude> with the
  /// world); the rest noted.
  void read_contact_section(const XMLElement* section);
  /// A unilateral contact for each shape of a moving body's geom that MuJoCo would collide with
  /// each plane of the world (contype/conaffinity), with MuJoCo's friction, plastic; the shapes
  /// momenta cannot pose noted.
  void add_contacts();

  // --- keyframes (mjcf_keyframes.cpp) ---------------------------------------------------------
  /// The <key>s of a <keyframe> section as states of the built `model`: MuJoCo's qpos and qvel
  /// turned into momenta's q and v (a hinge's or slide's q = qpos − ref, a free joint's velocity
  /// [ω; v] from MuJoCo's [v; ω]); what momenta has no use for (act, ctrl, mocap) noted. Appended
  /// to `keys` (an unnamed key is `key<i>`, i its index among all of the file's keys).
  void read_keyframes(const XMLElement* section, const model::Model& model,
                      std::vector<Keyframe>& keys);

 private:
  struct DefaultClass {
    std::string parent;                                             // empty for "main"
    std::map<std::string, const XMLElement*, std::less<>> entries;  // kind → <joint .../> etc.
  };
  void read_compiler(const XMLElement* e);
  void read_option(const XMLElement* e);
  void read_defaults(const XMLElement* e, const std::string& parent);
  void read_body(const XMLElement* e, const std::string& parent, const Transform& X_WP,
                 const std::string& child_class);
  void read_world_element(const XMLElement* e);
  /// A hinge's or slide's stops from its `range` and `limited`; none (a note says why where the
  /// file has a range) where they are not enforced.
  std::optional<model::JointLimits> joint_limits(const XMLElement* xml, const MjcfElement& e,
                                                 const std::string& owner, const std::string& type,
                                                 double ref);
  std::vector<std::string> body_joints(const XMLElement* body, const std::string& name,
                                       const std::string& parent, const Transform& X_PB,
                                       const Transform& X_WB, const std::string& child_class);
  const MjcfBody& body_named(const XMLElement* at, const char* attribute, const char* name) const;
  const MjcfJoint& joint_named(const XMLElement* at, const char* attribute, const char* name) const;
  /// The class an element names in `attribute` ("class", or a body's "childclass"), else
  /// `inherited`; fails at an unknown one with a did-you-mean.
  std::string class_of(const XMLElement* xml, const std::string& inherited,
                       const char* attribute = "class") const;
  /// A geom's mass or density (default 1000 kg/m³) as an amount, and its value.
  std::pair<inertia::Amount, double> geom_amount(const MjcfElement& e,
                                                 const std::string& label) const;
  /// A mesh geom as a part in the body frame, weighed when `weighed`; none (and a note) when it
  /// is not weighed and its file is missing.
  std::optional<PartSummary> mesh_geom(const MjcfElement& e, const std::string& label,
                                       const std::string& body, std::size_t index, bool weighed);
  /// The file of mesh asset `name` where it does not exist (none for an unknown name: mesh_asset
  /// fails there with a did-you-mean).
  std::optional<std::filesystem::path> missing_mesh_file(const std::string& name) const;
  /// The mesh asset `name`, read (once) and scaled; fails at `at` for an unknown name.
  std::shared_ptr<const inertia::TriangleMesh> mesh_asset(const XMLElement* at,
                                                          const std::string& name);

 public:
  // What the reading found, for the loads (mjcf_loads.cpp) and the geometry.
  const tinyxml2::XMLDocument& document;
  std::string_view text;
  std::string file;
  double angle_scale =
      3.14159265358979323846 / 180.0;  // <compiler angle="degree">, MuJoCo's default
  std::string euler_sequence = "xyz";
  std::string inertia_from_geom = "auto";
  bool auto_limits = true;          // <compiler autolimits>: a range makes a joint limited
  std::filesystem::path mesh_dir;   // the file's folder, then <compiler meshdir> or assetdir
  bool strip_path = false;          // <compiler strippath>
  bool exact_mesh_inertia = false;  // <compiler exactmeshinertia>
  model::ModelBuilder builder;
  std::vector<ItemLocation> items;
  std::map<std::string, MjcfBody, std::less<>> bodies;   // by the file's body name
  std::map<std::string, MjcfJoint, std::less<>> joints;  // by joint name
  // Fixed tendons by name, for the equalities and actuators that name them.
  std::map<std::string, model::FixedTendon, std::less<>> tendons;
  std::vector<model::OutputSpec> outputs;  // each fixed tendon's length
  std::vector<std::string> joint_order;
  std::map<std::string, std::vector<PartSummary>> body_parts;  // momenta body → geoms
  int body_count = 0, joint_count = 0;  // bodies and joints read so far: MuJoCo's numbers
  int tendon_count = 0;
  int world_geom_count = 0;  // the world's geoms read so far (an unnamed one is world_geom<i>)
  bool contacts_on = true;   // <option><flag contact="disable">: false
  std::vector<MjcfGeom> body_geoms;                  // every body's geoms, in the file's order
  std::vector<MjcfGeom> world_planes;                // the world's plane geoms
  std::set<std::string, std::less<>> moving_bodies;  // bodies some joint moves (file's names)
  std::set<std::string, std::less<>> excluded_from_world;  // <contact><exclude> with the world

 private:
  struct MeshAsset {
    const XMLElement* element;
    std::filesystem::path path;
    Vec3 scale;
    std::shared_ptr<const inertia::TriangleMesh> read;  // once a geom uses it
  };
  std::map<std::string, DefaultClass, std::less<>> classes_;
  std::map<std::string, MeshAsset, std::less<>> meshes_;
  bool mesh_inertia_noted_ = false;
  std::vector<std::pair<int, std::string>> notes_;  // line, text
};

/// "a box", "an ellipsoid": a geom's type for messages.
std::string shape_with_article(std::string_view type);

/// Where an item is declared (field by field: GCC 12 misreports a braced one's strings).
ItemLocation located_at(ModelItemRef::Kind kind, const std::string& name, int line, int column);

}  // namespace momenta::io::detail
