// The six volume integrals the SID terms are built from (MBSim's names; the SID of
// docs/references.md [R8]), recovered from a SID's terms: what an exporter to a tool that
// assembles its own terms (MBSim's flexible FFR body) needs. Exact for SIDs whose terms come
// from a consistent mass (isosid-prep's): the symmetric parts are in Oe, the antisymmetric
// ones in Cr (check_exportable compares the recovered trace with Me before MBSim export).
#pragma once
#include "isosid/format/sid.hpp"

#include <array>

namespace isosid::format {

struct BodyIntegrals {
  double m = 0;                              ///< int dm
  Eigen::Vector3d rdm;                       ///< int c dm
  Eigen::Matrix3d rrdm;                      ///< int c c^T dm
  Eigen::MatrixXd Pdm;                       ///< 3 x nq: int Phi dm
  std::array<Eigen::MatrixXd, 3> rPdm;       ///< [a]: 3 x nq, int c_a Phi dm
  std::array<std::array<Eigen::MatrixXd, 3>, 3> PPdm;  ///< [a][b]: nq x nq, int Phi_a^T Phi_b dm
};

BodyIntegrals body_integrals(const Sid& sid);

}  // namespace isosid::format
