// Moving a run's state from one multibody system to another that models the same bodies
// differently ([R2] Sect. 4.4, docs/references.md): a body changes between its coarse model and a
// model refined around an impact. The frames keep their position, orientation and velocities; the
// elastic coordinates map through the refined SID's /transfer.
#pragma once
#include "solve/multibody_system.hpp"

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace isosid::run {

/// How one body's elastic coordinates map: q_to = map q_from (all of the from-body's nq, its
/// quasistatic ones as last solved), and the to-body keeps its integrated ones. Empty: the
/// body is the same model in both systems.
using ElasticMap = Eigen::MatrixXd;

/// y_from (a state of `from`, its quasistatic coordinates solved for it) in the layout of `to`,
/// whose bodies are `from`'s in order; `maps[b]` for each body b. The dissipated energy carries
/// over. Elastic velocities of quasistatic coordinates are taken as zero (they carry no mass).
Eigen::VectorXd transfer_state(const MultibodySystem& from, const double* y_from, const MultibodySystem& to,
                               const std::vector<ElasticMap>& maps);

/// How far the refined SID's transfer misses the coarse SID the run uses, relative: the
/// displacements of `surface` per coarse mode, from the coarse master patch and from the
/// refined one through T, at a grid of its parameters. The coarse field lies in the refined
/// space, so they agree to the quadratures' difference unless the transfer was computed
/// against other coarse modes (a sign or a basis the eigensolver chose differently).
double transfer_mismatch(const format::Sid& coarse, const format::Sid& fine, const std::string& surface);

}  // namespace isosid::run
