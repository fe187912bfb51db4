// MJCF <keyframe>: each <key> a named state of the model, MuJoCo's qpos and qvel turned into
// momenta's q and v joint by joint (both lay the joints out in the file's depth-first order).

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mjcf/mjcf_reader.hpp"
#include "momenta/common/error.hpp"

namespace momenta::io::detail {

namespace {

// Which of a key's attributes momenta has no use for: activations, controls (momenta's inputs
// are its signals), mocap bodies (it has none).
constexpr std::string_view kUnused[] = {"act", "ctrl", "mpos", "mquat"};

}  // namespace

void MjcfReader::read_keyframes(const XMLElement* section, const model::Model& model,
                                std::vector<Keyframe>& keys) {
  for (const XMLElement* xml = section->FirstChildElement(); xml != nullptr;
       xml = xml->NextSiblingElement()) {
    if (std::string_view(xml->Name()) != "key") {
      fail(xml, fmt::format("<{}> in <keyframe>: its elements are <key>", xml->Name()));
    }
    check_attributes(xml, {"name", "time", "qpos", "qvel", "act", "mpos", "mquat", "ctrl"});
    const MjcfElement e{xml, "key", "main"};
    Keyframe key;
    const char* name = xml->Attribute("name");
    key.name = name != nullptr && *name != '\0' ? name : fmt::format("key{}", keys.size());
    for (const Keyframe& earlier : keys) {
      if (earlier.name == key.name) {
        fail(xml,
             fmt::format("a second key named '{}' (the first is at line {})", key.name,
                         earlier.line),
             "name");
      }
    }
    key.line = xml->GetLineNum();
    key.time = number(e, "time", 0.0);

    // MuJoCo's qpos0 is the configuration the file draws: momenta's initial q, each hinge's and
    // slide's shifted by its `ref` (a free joint starts where its body is drawn, a ball at the
    // identity). No qvel: at rest.
    const auto ref_of = [&](const model::Joint& joint) {
      const auto found = joints.find(joint.name);
      return found != joints.end() ? found->second.ref : 0.0;  // 0 but on hinges and slides
    };
    const std::size_t nq = static_cast<std::size_t>(model.nq());
    const std::size_t nv = static_cast<std::size_t>(model.nv());
    std::vector<double> qpos0(model.initial_q().begin(), model.initial_q().end()), zero(nv, 0.0);
    for (const model::Joint& joint : model.joints()) {
      if (joint.nq() == 1) qpos0[static_cast<std::size_t>(joint.q_index)] += ref_of(joint);
    }
    const std::vector<double> qpos = numbers(e, "qpos", nq, nq, qpos0);
    const std::vector<double> qvel = numbers(e, "qvel", nv, nv, zero);
    key.q = Eigen::Map<const VecX>(qpos.data(), model.nq());
    key.v.resize(model.nv());
    for (const model::Joint& joint : model.joints()) {
      if (joint.nq() == 1) key.q[joint.q_index] -= ref_of(joint);
      for (int k = 0; k < joint.nv(); ++k) {
        // A free joint's six speeds: MuJoCo's [v; ω], momenta's [ω; v] (rotation first).
        const int from = joint.type == model::JointType::free ? (k + 3) % 6 : k;
        key.v[joint.v_index + k] = qvel[static_cast<std::size_t>(joint.v_index + from)];
      }
    }
    std::vector<std::string_view> unused;
    for (std::string_view attribute : kUnused) {
      if (xml->Attribute(std::string(attribute).c_str()) != nullptr) unused.push_back(attribute);
    }
    if (!unused.empty()) {
      note(xml, fmt::format("key '{}': {} not used by momenta (its inputs are its signals; it has "
                            "no activations or mocap bodies)",
                            key.name, fmt::join(unused, ", ")));
    }
    keys.push_back(std::move(key));
  }
}

}  // namespace momenta::io::detail
