// A contact's normal law: what a contact point presses with at its gap. Every contact path asks
// its law instead of spelling one out: the Gauss-point surface contact (its loads and the energy
// of the penetration), the quasistatic modes' Newton model (pressure, stiffness and energy of the
// recorded points), gap space (whose complementarity problem needs a linear law) and the rigid
// spheres' Hertz contact. A law is one class in contact/ and one row in contact_law.cpp's table,
// whose name a scene's contact gives as its `law`.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace isosid::run {

class ContactLaw {
public:
  /// What the law's value is: a pressure on a surface's points (Pa, carried over each point's
  /// weight), or the force between two bodies touching at one point (N).
  enum class Kind { Pressure, Point };

  virtual ~ContactLaw() = default;
  virtual Kind kind() const = 0;
  /// The value at gap g (m, negative inside the target), zero where the point does not press.
  /// `multiplier`: the point's Lagrange multiplier under exact contact (augmented Lagrangian), else 0.
  virtual double pressure(double gap, double multiplier = 0) const = 0;
  /// -d pressure / d gap where the point presses (the Newton model's and Jacobian's stiffness).
  virtual double stiffness(double gap, double multiplier = 0) const = 0;
  /// The energy stored at gap g: the potential whose derivative in -g is the pressure, zero where
  /// the point does not press.
  virtual double energy(double gap, double multiplier = 0) const = 0;
  /// The gap shifted by the multiplier: the law presses exactly where this is negative.
  virtual double effective_gap(double gap, double multiplier) const = 0;
  /// c of a law p = max(0, lambda - c g), 0 for a law that is not linear: exact contact's
  /// augmentation and gap space's linear complementarity problem need it.
  virtual double linear_stiffness() const { return 0; }
};

/// What a law is built from.
struct ContactLawParameters {
  /// The law's scale: the penalty c_p (N/m^3) of a pressure law, K (N/m^1.5) of Hertz's.
  double stiffness = 0;
};

/// The law the table names `name`, built from `p`; nullptr for a name it does not hold.
std::unique_ptr<ContactLaw> make_contact_law(const std::string& name, const ContactLawParameters& p);
/// The kind of the law named `name`, nothing for a name the table does not hold.
std::optional<ContactLaw::Kind> contact_law_kind(const std::string& name);
/// The names of the table's laws of one kind.
std::vector<std::string> contact_law_names(ContactLaw::Kind kind);

}  // namespace isosid::run
