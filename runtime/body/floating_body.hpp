// A body in the floating frame of reference formulation, fed only by its SID: state r
// (world), unit quaternion, q; velocities v (world), omega (body frame), qdot. A rigid body
// is the same frame with no elastic coordinates (its SID comes from rigid_body_sid()).
// Equations of motion: docs/references.md [R8] (as MBSim's updateMb and CADyn assemble them).
#pragma once
#include "body/condensed_energy.hpp"
#include "body/modal_matrix.hpp"
#include "isosid/format/sid.hpp"
#include "body/body_spec.hpp"

#include <Eigen/Dense>
#include <array>

namespace isosid::run {

/// Generalized forces in body components: on the frame (force, torque about the origin) and
/// on the elastic coordinates, of which the equations read the integrated modes' (the leading
/// n_dynamic; point loads form only those, the quasistatic modes' are the static solve's).
struct GeneralizedForce {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  Eigen::VectorXd elastic;
  void reset(Eigen::Index nq) {
    force.setZero();
    torque.setZero();
    elastic.setZero(nq);
  }
};

class FloatingBody {
public:
  FloatingBody(const BodySpec& spec, format::Sid sid, Dimension dimension);

  const std::string& name() const { return name_; }
  const format::Sid& sid() const { return sid_; }
  /// Gives its SID up; the body is of no use after (a system built to look at a scene hands its
  /// SIDs on to the one that runs it).
  format::Sid release_sid() && { return std::move(sid_); }
  bool rigid() const { return spec_.rigid.has_value(); }
  Eigen::Index nq() const { return sid_.nq(); }
  /// Modes integrated in time (the leading ones); the rest are quasistatic, held outside the state.
  Eigen::Index n_dynamic() const { return n_dynamic_; }
  Eigen::Index n_quasistatic() const { return nq() - n_dynamic_; }
  /// Entries in the state vector: 7 + n_dynamic positions, then 6 + n_dynamic velocities.
  Eigen::Index state_size() const { return 13 + 2 * n_dynamic_; }
  void set_offset(Eigen::Index offset) { offset_ = offset; }
  Eigen::Index offset() const { return offset_; }

  void initial_state(double* y) const;

  // --- views of the state (y is the whole system state) ---
  Eigen::Map<const Eigen::Vector3d> r(const double* y) const { return Eigen::Map<const Eigen::Vector3d>(y + offset_); }
  Eigen::Quaterniond orientation(const double* y) const;
  /// All nq elastic coordinates: the dynamic ones from y, the quasistatic ones as last set.
  const Eigen::VectorXd& q(const double* y) const;
  /// Elastic velocities (zero for quasistatic modes).
  const Eigen::VectorXd& qdot(const double* y) const;
  Eigen::Map<const Eigen::Vector3d> v(const double* y) const { return Eigen::Map<const Eigen::Vector3d>(y + offset_ + 7 + n_dynamic_); }
  Eigen::Map<const Eigen::Vector3d> omega(const double* y) const { return Eigen::Map<const Eigen::Vector3d>(y + offset_ + 10 + n_dynamic_); }
  /// The quasistatic modes' values (set by the quasistatic solve before each use of q): the
  /// tail of the vector q() returns, kept there so that q() copies only the integrated modes.
  Eigen::VectorBlock<Eigen::VectorXd> quasistatic_modes() const { return q_full_.tail(q_full_.size() - n_dynamic_); }
  /// Where this body's quasistatic modes start in the system's stacked quasistatic vector.
  Eigen::Index quasistatic_offset() const { return quasistatic_offset_; }
  void set_quasistatic_offset(Eigen::Index offset) { quasistatic_offset_ = offset; }

  /// Time derivative of this body's state under the applied forces `applied` (body frame)
  /// and gravity (world); quasistatic modes carry no inertia ([R2]). Returns the
  /// dissipated power of the modal damping.
  double derivatives(const double* y, const GeneralizedForce& applied, const Eigen::Vector3d& gravity, double* ydot) const;

  /// The accelerations (into ydot, the whole system's derivative, at this body's velocity
  /// rates) that `load` alone adds, with the mass matrix of the last derivatives() call: the
  /// response is linear in the load (joint reactions are solved from it).
  void load_response(const GeneralizedForce& load, double* ydot) const;

  /// Adds the loads on the quasistatic modes at y that do not depend on them to out
  /// (n_quasistatic entries): the rotation loads (-Ge(qdot) w - Oe(q) w^2, a spinning body's
  /// centrifugal deformation), where Ke couples them to the integrated modes (a MacNeal SID's
  /// boundary) -K_hd q_d, and gravity (world, m/s^2) where the frame is held (all six DOFs
  /// locked): Ct_h A^T g. Elsewhere gravity and the frame's accelerations are left out
  /// together: quasistatic modes carry no inertia, so no inertia relief either; on a free body
  /// the two cancel (and its free-free normal modes have Ct = 0 besides).
  void add_quasistatic_loads(const double* y, const Eigen::Vector3d& gravity, Eigen::Ref<Eigen::VectorXd> out) const;
  /// The same loads but the coupling: the rotation and held-gravity loads. False (and out
  /// untouched) where the body has neither: its frame cannot turn or its quasistatic
  /// coordinates carry no inertia (a massless boundary), and it holds no weight (a held frame
  /// in a scene with gravity).
  bool add_uncoupled_quasistatic_loads(const double* y, const Eigen::Vector3d& gravity, Eigen::Ref<Eigen::VectorXd> out) const;
  /// An upper bound on how far the rotation loads on the quasistatic modes at (q, qdot, w) can
  /// move any point of the body (m): their size through the Frobenius norms of Ge's and Oe's
  /// quasistatic rows, over the smallest eigenvalue of Ke's held block (contact only stiffens
  /// it), times the largest displacement per unit coordinate of a node, contact point or
  /// control point. Infinity where the body carries no such loads.
  double rotation_response_bound(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, const Eigen::Vector3d& w) const;
  /// The same bound for each of the loads' three terms: Ge(qdot) w, Oe0 w^2 and the
  /// first-order Oe1(q) w^2 (their sum is rotation_response_bound).
  std::array<double, 3> rotation_term_bounds(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, const Eigen::Vector3d& w) const;
  /// What a displacement must exceed to change a point's position: the rounding of the body's
  /// largest reference coordinate (m); formed only where rotation loads on the quasistatic
  /// modes are bounded (0 elsewhere).
  double position_resolution() const { return rotation_bound_.resolution; }
  /// Ke's block that couples the quasistatic modes to the integrated ones (quasistatic rows,
  /// integrated columns): the loads -K_hd q_d; empty where it is zero (normal form).
  const Eigen::MatrixXd& quasistatic_coupling() const { return quasistatic_coupling_; }

  // --- energies ---
  double kinetic_energy(const double* y) const;
  double elastic_energy(const double* y) const;
  double gravity_potential(const double* y, const Eigen::Vector3d& gravity) const;

  /// Energy of each mode that carries mass (all but a massless boundary), J:
  /// E_k = 1/2 (qdot_k^2 + omega_k^2 q_k^2) with the SID's frequencies ([R3]'s modal energy).
  /// For a SID in normal form they partition the elastic energy exactly; for a massless-boundary
  /// SID once its boundary is free (it then follows the modes: u_b = Phi_b eta).
  Eigen::VectorXd modal_energies(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) const;

  // --- points of the body ---
  /// World velocity of the body-frame point P as if the body were rigid: v + A (omega x P).
  Eigen::Vector3d rigid_point_velocity(const Eigen::Vector3d& body_point, const double* y) const;
  /// World velocity of the body-frame point P (3D) whose displacement rows are Psi.
  Eigen::Vector3d point_velocity(const Eigen::Vector3d& body_point, const Eigen::Ref<const Eigen::MatrixXd>& Psi,
                                 const double* y) const;
  /// Adds a world force F at a body point with shape rows Psi to the generalized forces.
  void apply_force(const Eigen::Vector3d& F_world, const Eigen::Vector3d& body_point,
                   const Eigen::Ref<const Eigen::MatrixXd>& Psi, const Eigen::Matrix3d& A, GeneralizedForce& f) const;

  /// Position and velocity (world) of a SID node. The quasistatic coordinates have no velocity
  /// in the state: `quasistatic_rate` (n_quasistatic entries), if given, is theirs.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> node_state(const format::Node& node, const double* y,
                                                         const Eigen::VectorXd* quasistatic_rate = nullptr) const;
  const format::Node* node(const std::string& name) const;
  const format::ContactSurface* contact_surface(const std::string& name) const;
  const std::array<bool, 6>& locked() const { return locked_; }
  /// Ke as applied (diagonal or dense).
  const ModalMatrix& stiffness() const { return stiffness_; }

private:
  /// out -= rows [first, first + out.size()) of Ge(qdot) w + Oe(q) w^2: the integrated modes
  /// need their rows, the static solve the others. False (a no-op) where those rows carry no
  /// rotation loads: the body cannot rotate, or they are a massless boundary's. On the
  /// quasistatic modes the smallest terms are left out while together they could not move any
  /// point by the position resolution (a centric impact leaves the sphere on the beam turning
  /// at 4e-10 rad/s; an eccentric one at 0.1 rad/s, whose first-order term is then far below).
  bool add_rotation_loads(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, const Eigen::Vector3d& w, Eigen::Index first,
                          Eigen::Ref<Eigen::VectorXd> out) const;

  std::string name_;
  format::Sid sid_;
  BodySpec spec_;
  ModalMatrix stiffness_, damping_;  ///< Ke, De
  /// Ke's energy through the held coordinates' condensation, where Ke is dense and couples them
  std::optional<CondensedEnergy> condensed_energy_;
  Eigen::MatrixXd quasistatic_coupling_;  ///< Ke's block (quasistatic rows, integrated columns) if not zero
  Eigen::MatrixXd held_gravity_rows_;     ///< Ct's quasistatic rows (zeroth order) if the frame is held and they are not zero
  std::array<bool, 6> locked_{};  ///< x y z rx ry rz (body-frame accelerations)
  bool rotates_ = true;           ///< false if all rotations are locked: rotational terms vanish
  Eigen::Index offset_ = 0;
  Eigen::Index n_dynamic_ = 0;
  Eigen::Index n_inertial_ = 0;  ///< leading coordinates the inertia terms involve (all but a massless boundary)
  Eigen::Index quasistatic_offset_ = 0;
  /// The mass matrix at the last derivatives() call, factored: A6 - B^T B on the unlocked
  /// rigid DOFs (its Schur complement), and the orientation; B itself stays in B_.
  struct MassFactor {
    using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;  // on the stack
    using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
    Eigen::LDLT<Small> S;
    int free_dofs[6] = {0, 0, 0, 0, 0, 0};
    int free = 0;
    Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  };
  /// ydot's velocity rates from the generalized loads hr (rigid) and hd (dynamic modes).
  void accelerations_from(const Eigen::Matrix<double, 6, 1>& hr, const Eigen::Ref<const Eigen::VectorXd>& hd, double* d) const;
  /// The mass matrix's floating-frame terms at q as the equations and the kinetic energy read
  /// them: mc and J, and the leading rows of Ct and Cr (the coordinates with velocities), into
  /// the caller's storage (the right-hand side must not allocate); Cr zero and J constant for a
  /// frame that cannot turn.
  void inertia_at(const Eigen::VectorXd& q, Eigen::Vector3d& mc, Eigen::Ref<Eigen::MatrixXd> Ct, Eigen::Ref<Eigen::MatrixXd> Cr,
                  Eigen::Matrix3d& J) const;
  mutable MassFactor mass_;
  mutable Eigen::VectorXd q_full_, qdot_full_;
  /// The terms of rotation_response_bound, formed once: the Frobenius norms of Ge's, Oe0's
  /// and Oe1's quasistatic rows, the largest displacement per unit load (m/N: the largest
  /// point's mode rows over the smallest quasistatic stiffness; 0: no bound), the resolution.
  struct RotationBound {
    double ge = 0, oe0 = 0, oe1 = 0, per_load = 0, resolution = 0;
  } rotation_bound_;
  void form_rotation_bound();
  /// Oe's first-order terms side by side, [Oe1_0 ... Oe1_(n_inertial - 1)], their leading
  /// n_inertial rows (n_inertial x 6 n_inertial): column c of all of them is then a matrix
  /// with a stride of six columns, and Oe1(q) w^2 a product of those for w^2's non-zero c with q
  Eigen::MatrixXd oe1_;
  // workspace of derivatives(): [Ct(q) Cr(q)], h_q, in their leading n_dynamic rows
  mutable Eigen::MatrixXd B_;
  mutable Eigen::VectorXd hq_;
};

/// out += Psi^T F for shape rows Psi (dim x n, dim <= 3) and the first dim components of a
/// body-frame force F: the generalized elastic force of a point load. Row by row, which also
/// keeps GCC 12's -Warray-bounds quiet about vectorized reads of a partial fixed-size vector.
/// A rigid body's shape rows have no columns (and no data to index): nothing to add.
inline void add_elastic_force(const Eigen::Ref<const Eigen::MatrixXd>& Psi, const Eigen::Vector3d& F, Eigen::Ref<Eigen::VectorXd> out) {
  if (Psi.cols() == 0) return;
  for (Eigen::Index a = 0; a < Psi.rows(); ++a) out.noalias() += F(a) * Psi.row(a).transpose();
}

/// The frame DOFs x y z rx ry rz, as a body's `locked` list names them.
inline constexpr std::array<const char*, 6> kFrameDofNames = {"x", "y", "z", "rx", "ry", "rz"};
/// The frame DOFs held at zero: those a scene of `dimension` locks (axisymmetric: all but y;
/// planar: z, rx, ry) and those `locked` names.
std::array<bool, 6> locked_dofs(Dimension dimension, const std::vector<std::string>& locked);

/// Rotation matrix of Tait-Bryan angles (x, y, z): Rx(a) Ry(b) Rz(c) ([R1] eq. 20).
Eigen::Matrix3d tait_bryan_matrix(const Eigen::Vector3d& angles);
/// Inverse of tait_bryan_matrix (beta in [-pi/2, pi/2]).
Eigen::Vector3d tait_bryan_angles(const Eigen::Matrix3d& A);

}  // namespace isosid::run
