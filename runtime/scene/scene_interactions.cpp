// The scene's contacts, joints and monitors, which refer to its bodies; see scene_reading.hpp.
#include "scene/scene_reading.hpp"

#include "contact/contact_law.hpp"

#include <algorithm>

namespace isosid::run::scene_reading {
namespace {

void read_contacts(const TomlView& top, ItemNames& names, Scene& scene) {
  for (const TomlView& c : top.tables("contact")) {
    c.allow_only({"name", "body", "surface", "target", "target_surface", "law", "penalty", "friction", "regularization", "enforcement", "formulation"});
    ContactSpec s;
    s.name = names.take(c);
    s.body = c.string("body");
    s.surface = c.string("surface");
    s.target = c.string("target");
    s.target_surface = c.string("target_surface", "");
    s.law = c.string("law", s.law);
    if (contact_law_kind(s.law) != ContactLaw::Kind::Pressure) {
      std::string laws;
      for (const std::string& name : contact_law_names(ContactLaw::Kind::Pressure)) laws += (laws.empty() ? "" : ", ") + name;
      c.fail("law", "'" + s.law + "' is not a law of surface contact (" + laws + ")");
    }
    const bool linear = make_contact_law(s.law, {1.0})->linear_stiffness() > 0;
    s.penalty = c.positive("penalty", 0.0);  // 0: derived from the bodies (contact/default_penalty.hpp)
    s.friction = c.number("friction", 0.0);
    if (s.friction < 0 || s.friction > 10) c.fail("friction", "must lie in [0, 10]");
    s.regularization = c.positive("regularization", s.regularization);
    // the friction law's slope at rest is friction x normal force / regularization: below 1e-9
    // m/s it is a step no solver resolves, above 1 m/s friction hardly acts in an impact
    if (s.regularization < 1e-9 || s.regularization > 1)
      c.fail("regularization", "must lie in [1e-9, 1] m/s (the sliding speed below which friction is smoothed)");
    const std::string enforcement = c.string("enforcement", "penalty");
    if (enforcement != "penalty" && enforcement != "exact") c.fail("enforcement", "must be penalty or exact");
    s.exact = enforcement == "exact";
    // the augmented Lagrangian solves the boundary at the start of each fixed step; under an
    // adaptive integrator its contact set switches inside the stages and the steps chatter
    if (s.exact && scene.simulation.integrator != IntegratorKind::Leapfrog)
      c.fail("enforcement", "exact contact needs integrator = \"leapfrog\"");
    const std::string formulation = c.string("formulation", "general");
    if (formulation != "general" && formulation != "gap-space") c.fail("formulation", "must be general or gap-space");
    s.gap_space = formulation == "gap-space";
    if ((s.exact || s.gap_space) && !linear)
      c.fail("law", (s.exact ? "exact contact" : "gap-space contact") + std::string(" needs a linear law (penalty), not '") + s.law + "'");
    if (s.gap_space && s.exact) c.fail("formulation", "gap-space contact is penalty contact (enforcement = \"penalty\")");
    if (s.gap_space && s.friction > 0) c.fail("formulation", "gap-space contact is frictionless (friction = 0)");
    const BodySpec* slave = scene.body(s.body);
    if (!slave || slave->rigid) c.fail("body", "no flexible_body named '" + s.body + "' (the slave side carries the contact points)");
    const BodySpec* master = scene.body(s.target);
    if (!master && !scene.fixed_surface(s.target)) c.fail("target", "no fixed surface or body named '" + s.target + "'");
    if (master == slave) c.fail("target", "a body cannot be its own contact target");
    if (master && !master->rigid && s.target_surface.empty())
      c.fail("target_surface", "a flexible target needs the contact surface whose master patch it offers");
    if ((!master || master->rigid) && !s.target_surface.empty())
      c.fail("target_surface", "only a flexible target has contact surfaces");
    scene.contacts.push_back(s);
  }
}

void read_hertz_contacts(const TomlView& top, ItemNames& names, Scene& scene) {
  for (const TomlView& c : top.tables("hertz_contact")) {
    c.allow_only({"name", "body", "target", "youngs_modulus", "poisson_ratio", "target_youngs_modulus", "target_poisson_ratio"});
    HertzContactSpec s;
    s.name = names.take(c);
    s.body = c.string("body");
    s.target = c.string("target");
    for (const char* key : {"body", "target"}) {
      const BodySpec* b = scene.body(c.string(key));
      if (!b || !b->rigid || b->rigid->kind != RigidShape::Kind::Sphere)
        c.fail(key, "no rigid_body sphere named '" + c.string(key) + "' (Hertz's law is between rigid spheres)");
    }
    if (s.body == s.target) c.fail("target", "a sphere cannot touch itself");
    s.youngs_modulus[0] = c.positive("youngs_modulus");
    s.poisson_ratio[0] = c.number("poisson_ratio");
    s.youngs_modulus[1] = c.positive("target_youngs_modulus", s.youngs_modulus[0]);
    s.poisson_ratio[1] = c.number("target_poisson_ratio", s.poisson_ratio[0]);
    for (int side = 0; side < 2; ++side)
      if (!(s.poisson_ratio[std::size_t(side)] > -1 && s.poisson_ratio[std::size_t(side)] < 0.5))
        c.fail(side ? "target_poisson_ratio" : "poisson_ratio", "must lie in (-1, 0.5)");
    scene.hertz_contacts.push_back(s);
  }
}

void read_joints(const TomlView& top, ItemNames& names, Scene& scene) {
  for (const TomlView& j : top.tables("joint")) {
    j.allow_only({"name", "type", "body", "node", "other", "other_node", "point", "axis"});
    JointSpec s;
    s.name = names.take(j);
    const std::string type = j.string("type");
    if (type == "spherical") s.kind = JointSpec::Kind::Spherical;
    else if (type == "revolute") s.kind = JointSpec::Kind::Revolute;
    else if (type == "fixed") s.kind = JointSpec::Kind::Fixed;
    else j.fail("type", "unknown joint type '" + type + "' (spherical, revolute, fixed)");
    if (scene.simulation.dimension == Dimension::Axisymmetric) j.fail("type", "an axisymmetric scene has no joints");
    s.body = j.string("body");
    s.node = j.string("node", "");
    s.other = j.string("other", "");
    s.other_node = j.string("other_node", "");
    // each side: a flexible body at one of its SID nodes, a rigid body, or (second side) the ground
    auto side = [&](const std::string& body, const std::string& node, const char* body_key, const char* node_key) {
      const BodySpec* b = scene.body(body);
      if (!b) j.fail(body_key, "no body named '" + body + "'");
      if (!b->rigid && node.empty()) j.fail(node_key, "a flexible body attaches at one of its SID nodes: name it");
      if (b->rigid && !node.empty()) j.fail(node_key, "a rigid body has no nodes: give the joint's point");
      return b->rigid.has_value();
    };
    bool rigid_side = side(s.body, s.node, "body", "node");
    if (!s.other.empty()) {
      if (s.other == s.body) j.fail("other", "a body cannot be jointed to itself");
      rigid_side = side(s.other, s.other_node, "other", "other_node") || rigid_side;
    } else if (!s.other_node.empty()) {
      j.fail("other_node", "the ground has no nodes");
    }
    // without a point the joint sits at the (first) node: the ground holds on to it there
    if (j.has("point")) s.point = vec3(j, "point", Eigen::Vector3d::Zero());
    else if (rigid_side) j.fail("point", "a rigid body attaches at the joint's point: give it (world, at t = 0)");
    if (j.has("axis") && s.kind != JointSpec::Kind::Revolute) j.fail("axis", "only a revolute joint has an axis");
    s.axis = unit_vector(j, "axis", s.axis);
    scene.joints.push_back(s);
  }
}

void read_monitors(const TomlView& top, ItemNames& names, Scene& scene) {
  for (const TomlView& m : top.tables("monitor")) {
    m.allow_only({"name", "body", "node", "surface", "parameter", "quantity", "stress"});
    const std::string name = names.take(m);
    const BodySpec* body = scene.body(m.string("body"));
    if (!body || body->rigid) m.fail("body", "no flexible_body named '" + m.string("body") + "'");
    if (m.has("stress")) {
      for (const char* other : {"node", "surface", "parameter", "quantity"})
        if (m.has(other)) m.fail(other, "a stress monitor takes only name, body and stress");
      scene.stress_monitors.push_back({name, body->name, m.string("stress")});
      continue;
    }
    MonitorSpec s;
    s.name = name;
    s.body = body->name;
    if (m.has("node") == m.has("surface")) m.fail("node", "give either a node or a surface and a parameter");
    s.node = m.string("node", "");
    s.surface = m.string("surface", "");
    if (!s.surface.empty()) {
      s.parameter = m.numbers("parameter");
      if (s.parameter.empty() || s.parameter.size() > 2) m.fail("parameter", "needs one or two master-patch parameters");
    } else if (m.has("parameter")) {
      m.fail("parameter", "only used with a surface");
    }
    s.quantity = m.string("quantity", s.quantity);
    if (s.quantity != "velocity" && s.quantity != "position") m.fail("quantity", "must be velocity or position");
    scene.monitors.push_back(s);
  }
}

}  // namespace

void read_interactions(const TomlView& top, ItemNames& names, Scene& scene) {
  read_contacts(top, names, scene);
  read_hertz_contacts(top, names, scene);
  read_joints(top, names, scene);
  if (std::none_of(scene.bodies.begin(), scene.bodies.end(), [](const BodySpec& b) { return !b.rigid; }) && scene.joints.empty() &&
      scene.hertz_contacts.empty())
    top.fail("flexible_body", "a scene needs at least one flexible body (or rigid bodies in joints or Hertz contacts)");
  read_monitors(top, names, scene);
}

}  // namespace isosid::run::scene_reading
