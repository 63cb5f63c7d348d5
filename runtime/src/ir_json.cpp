// A minimal JSON writer for the IR: values built as a tree whose objects are std::maps, so keys come
// out sorted; numbers via std::to_chars, which ignores the locale.
#include "rbdc/ir_json.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <memory>
#include <variant>
#include <vector>

namespace rbdc {
namespace {

struct Json;
using JsonArray = std::vector<Json>;
using JsonObject = std::map<std::string, Json>;

struct Null {};
struct Number {
  double value;
};

struct Json {
  std::variant<Null, bool, int, Number, std::string, JsonArray, JsonObject> value;
  Json() : value(Null{}) {}
  Json(bool b) : value(b) {}
  Json(int i) : value(i) {}
  Json(double d) : value(Number{d}) {}
  Json(const char* s) : value(std::string(s)) {}
  Json(std::string s) : value(std::move(s)) {}
  Json(JsonArray a) : value(std::move(a)) {}
  Json(JsonObject o) : value(std::move(o)) {}
};

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20) {
      static const char* hex = "0123456789abcdef";
      out += "\\u00";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

bool is_flat(const JsonArray& a) {
  for (const Json& x : a) {
    if (std::holds_alternative<JsonArray>(x.value) || std::holds_alternative<JsonObject>(x.value)) {
      return false;
    }
  }
  return true;
}

// Arrays of scalars go on one line; everything else one element per line, two-space indents.
void write(const Json& j, int indent, std::string& out) {
  const std::string pad(static_cast<size_t>(indent + 2), ' ');
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Null>) {
          out += "null";
        } else if constexpr (std::is_same_v<T, bool>) {
          out += v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, int>) {
          out += std::to_string(v);
        } else if constexpr (std::is_same_v<T, Number>) {
          out += json_number(v.value);
        } else if constexpr (std::is_same_v<T, std::string>) {
          out += quoted(v);
        } else if constexpr (std::is_same_v<T, JsonArray>) {
          const bool flat = is_flat(v);
          out += "[";
          for (size_t k = 0; k < v.size(); ++k) {
            out += k == 0 ? "" : (flat ? ", " : ",");
            if (!flat) out += "\n" + pad;
            write(v[k], indent + 2, out);
          }
          if (!flat && !v.empty()) out += "\n" + std::string(static_cast<size_t>(indent), ' ');
          out += "]";
        } else {
          out += "{";
          bool first = true;
          for (const auto& [key, value] : v) {
            out += first ? "\n" : ",\n";
            first = false;
            out += pad + quoted(key) + ": ";
            write(value, indent + 2, out);
          }
          out += v.empty() ? "}" : "\n" + std::string(static_cast<size_t>(indent), ' ') + "}";
        }
      },
      j.value);
}

Json vector_json(const Vector3& v) { return JsonArray{v.x(), v.y(), v.z()}; }

Json matrix_json(const Matrix3& m) {
  JsonArray rows;
  for (int r = 0; r < 3; ++r) rows.push_back(vector_json(m.row(r).transpose()));
  return rows;
}

Json int_list(const std::vector<int>& v, size_t from = 0) {
  JsonArray a;
  for (size_t k = from; k < v.size(); ++k) a.push_back(v[k]);
  return a;
}

Json int_lists(const std::vector<std::vector<int>>& v) {
  JsonArray a;
  for (const std::vector<int>& x : v) a.push_back(int_list(x));
  return a;
}

Json limit_json(double x) { return std::isinf(x) ? Json() : Json(x); }

const char* type_name(JointType t) {
  switch (t) {
    case JointType::Floating: return "floating";
    case JointType::Fixed: return "fixed";
    case JointType::Revolute: return "revolute";
    case JointType::Prismatic: return "prismatic";
  }
  return "unknown";
}

// Joint i's actuator (docs/ir.md): written only when it has one, so models without actuators keep
// their IR byte for byte.
bool has_actuator(const Joint& j) { return j.armature != 0 || j.rotor.gear_ratio != 0; }

Json actuator_json(const Joint& j) {
  JsonObject a{{"armature", j.armature}};
  if (j.rotor.gear_ratio != 0) {
    const Rotor& r = j.rotor;
    a.emplace("rotor", JsonObject{{"gear_ratio", r.gear_ratio},
                                  {"mass", r.mass},
                                  {"inertia", matrix_json(r.inertia)},
                                  {"rotation", matrix_json(r.rotation)},
                                  {"translation", vector_json(r.translation)},
                                  {"axis", vector_json(r.axis)}});
  }
  return a;
}

}  // namespace

std::string json_number(double x) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 17);
  return std::string(buf, result.ptr);
}

std::string to_ir_json(const Model& m) {
  JsonArray bodies, joints, feet, frames, couplings;
  for (const Body& b : m.bodies) {
    bodies.push_back(JsonObject{{"name", b.name}, {"mass", b.mass}, {"com", vector_json(b.com)},
                                {"inertia_com", matrix_json(b.inertia_com)}});
  }
  for (int i = 0; i < m.nb; ++i) {
    const Joint& j = m.joints[static_cast<size_t>(i)];
    JsonObject joint{{"name", j.name},
                     {"type", type_name(j.type)},
                     {"parent", m.parent[static_cast<size_t>(i)]},
                     {"axis", vector_json(j.axis)},
                     {"rotation", matrix_json(j.rotation)},
                     {"translation", vector_json(j.translation)},
                     {"q_index", j.q_index},
                     {"v_index", j.v_index},
                     {"lower", limit_json(j.lower)},
                     {"upper", limit_json(j.upper)}};
    if (has_actuator(j)) joint.emplace("actuator", actuator_json(j));
    joints.push_back(std::move(joint));
  }
  for (const Foot& f : m.feet) {
    feet.push_back(JsonObject{{"name", f.name}, {"body", f.body}, {"offset", vector_json(f.offset)}});
  }
  for (const Frame& f : m.frames) {
    frames.push_back(JsonObject{{"name", f.name}, {"body", f.body}, {"rotation", matrix_json(f.rotation)},
                                {"translation", vector_json(f.translation)}});
  }
  for (const Coupling& c : m.couplings) {
    couplings.push_back(JsonObject{{"follower", c.follower}, {"leader", c.leader},
                                   {"multiplier", c.multiplier}, {"offset", c.offset}});
  }
  const JsonObject ir{{"format", "rbdc-ir-1"},
                      {"name", m.name},
                      {"floating_base", m.floating_base},
                      {"gravity", vector_json(m.gravity)},
                      {"nb", m.nb},
                      {"nq", m.nq},
                      {"nv", m.nv},
                      {"PRED", int_list(m.pred, 1)},
                      {"SUCC", int_list(m.succ, 1)},
                      {"lambda", int_list(m.parent, 1)},
                      {"kappa", int_lists(m.support)},
                      {"mu", int_lists(m.children)},
                      {"nu", int_lists(m.subtree)},
                      {"bodies", std::move(bodies)},
                      {"joints", std::move(joints)},
                      {"feet", std::move(feet)},
                      {"frames", std::move(frames)},
                      {"couplings", std::move(couplings)}};
  std::string out;
  write(ir, 0, out);
  return out + "\n";
}

}  // namespace rbdc
