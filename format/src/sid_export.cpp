// SID export; see sid_export.hpp. Layouts: docs/references.md [R12], the EMBS
// reader (vwaurich/EMBS_ModelicaLib, EMBSlib/Resources/Include/ReadSID_C.h) and its sample
// beam.SID_FEM; MBSim's external_flexible_ffr_body.cc and fbt_lma.cc.
#include "isosid/format/sid_export.hpp"

#include "isosid/format/atomic_output.hpp"
#include "isosid/format/body_integrals.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/hdf5_file.hpp"
#include "isosid/version.hpp"

#include <cstdio>
#include <string>

namespace isosid::format {
namespace {

/// A value as EMBS reads it: mantissa and D exponent, 15 significant digits (its buffers
/// hold 19 characters; round trip 5e-15).
std::string fortran(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "% .14E", v);
  std::string s = text;
  s[s.find('E')] = 'D';
  return s;
}

/// "key<padding>= " at the given indentation, '=' in a fixed column as in the sample files.
std::string key(int indent, const std::string& name) {
  std::string line(std::size_t(indent), ' ');
  line += name;
  if (line.size() < 48) line.resize(48, ' ');
  return line + "= ";
}

class SidFemText {
public:
  explicit SidFemText(Eigen::Index nq) : nq_(nq) {}
  std::string text;

  void line(int indent, const std::string& s) { text += std::string(std::size_t(indent), ' ') + s + "\n"; }
  void value(int indent, const std::string& name, const std::string& v) { text += key(indent, name) + v + "\n"; }

  /// One Taylor block: header, then the non-zero entries (readers take missing ones as 0);
  /// structure 3 (no particular structure) when M0 has an entry, else 0.
  void taylor(int indent, const std::string& name, const Eigen::MatrixXd& M0, const std::vector<Eigen::MatrixXd>& M1) {
    line(indent, name);
    const int in = indent + 5;
    char entry[64];
    value(in, "order", std::to_string(M1.empty() ? 0 : 1));
    value(in, "nrow", std::to_string(M0.rows()));
    value(in, "ncol", std::to_string(M0.cols()));
    value(in, "nq", std::to_string(nq_));
    value(in, "nqn", "0");
    value(in, "structure", M0.cwiseAbs().maxCoeff() > 0 ? "3" : "0");
    for (Eigen::Index i = 0; i < M0.rows(); ++i)
      for (Eigen::Index j = 0; j < M0.cols(); ++j)
        if (M0(i, j) != 0) {
          std::snprintf(entry, sizeof entry, "m0(%3ld,%3ld)", long(i + 1), long(j + 1));
          value(in, entry, fortran(M0(i, j)));
        }
    for (std::size_t q = 0; q < M1.size(); ++q)  // m1(row, q, col): the EMBS reader's and the sample's order
      for (Eigen::Index i = 0; i < M1[q].rows(); ++i)
        for (Eigen::Index j = 0; j < M1[q].cols(); ++j)
          if (M1[q](i, j) != 0) {
            std::snprintf(entry, sizeof entry, "m1(%3ld,%3ld,%3ld)", long(i + 1), long(q + 1), long(j + 1));
            value(in, entry, fortran(M1[q](i, j)));
          }
    line(indent, "end " + name);
  }
  void taylor(int indent, const std::string& name, const Taylor& t) { taylor(indent, name, t.M0, t.M1); }

private:
  Eigen::Index nq_;
};

/// J as EMBS expands it: 6 x 1, xx yy zz xy xz yz.
Eigen::MatrixXd inertia_column(const Eigen::MatrixXd& J) {
  Eigen::MatrixXd c(6, 1);
  c << J(0, 0), J(1, 1), J(2, 2), J(0, 1), J(0, 2), J(1, 2);
  return c;
}

Eigen::MatrixXd symmetrized(const Eigen::MatrixXd& m) { return 0.5 * (m + m.transpose()); }

}  // namespace

void check_exportable(const Sid& sid, const std::string& sid_file, ExportFormat format) {
  if (sid.refmod.massless_boundary())
    throw InputError(sid_file, "/refmod/reduction_method",
                     sid.refmod.reduction_method + " leaves coordinates without mass, which SID_FEM and MBSim readers integrate dynamically");
  if (format != ExportFormat::MbsimH5) return;
  const BodyIntegrals b = body_integrals(sid);
  const Eigen::MatrixXd trace = b.PPdm[0][0] + b.PPdm[1][1] + b.PPdm[2][2];
  const double scale = sid.Me.M0.cwiseAbs().maxCoeff();
  if ((trace - sid.Me.M0).cwiseAbs().maxCoeff() > 1e-8 * scale)
    throw InputError(sid_file, "/terms/Oe", "its order-1 part does not give back the integrals of Phi^T Phi (their trace is not Me): "
                                            "MBSim's input cannot be recovered from this SID");
}

void write_sid_fem(const Sid& sid, const std::string& path) {
  const Eigen::Index nq = sid.nq();
  SidFemText out(nq);
  char header[160];
  // the reader takes the first two runs of digits: the node and mode counts
  std::snprintf(header, sizeof header, "%5zu %5ld    :No. nodes, No. modes: written by isosid-export from the SID of '%s'",
                sid.nodes.size(), long(nq), sid.body_name.c_str());
  out.text += header;
  out.text += "\n";
  out.line(1, "part");
  out.value(6, "new modal", "");
  out.line(11, "refmod");
  out.value(16, "mass", fortran(sid.refmod.mass));
  out.value(16, "nelastq", std::to_string(nq));
  char name[32];
  for (Eigen::Index k = 0; k < nq; ++k) {
    std::snprintf(name, sizeof name, "ielastq (%4ld)", long(k + 1));
    out.value(16, name, sid.refmod.mode_names[std::size_t(k)]);
  }
  out.line(11, "end refmod");
  out.line(11, "frame");
  for (std::size_t n = 0; n < sid.nodes.size(); ++n) {
    const Node& node = sid.nodes[n];
    out.value(16, "new node", std::to_string(n + 1));
    out.value(21, "rframe", "body ref");
    out.taylor(21, "origin", node.origin);
    out.taylor(21, "phi", node.phi, {});
    out.taylor(21, "psi", node.psi, {});
    out.taylor(21, "AP", node.AP);
    out.line(16, "end node");
  }
  out.line(11, "end frame");
  out.taylor(11, "mdCM", sid.mdCM);
  std::vector<Eigen::MatrixXd> J1;
  for (const Eigen::MatrixXd& m : sid.J.M1) J1.push_back(inertia_column(m));
  out.taylor(11, "J", inertia_column(sid.J.M0), J1);
  for (const auto& [label, term] : {std::pair{"Ct", &sid.Ct}, {"Cr", &sid.Cr}, {"Me", &sid.Me}, {"Gr", &sid.Gr},
                                    {"Ge", &sid.Ge}, {"Oe", &sid.Oe}, {"ksigma", &sid.ksigma}, {"Ke", &sid.Ke}, {"De", &sid.De}})
    out.taylor(11, label, *term);
  out.line(6, "end modal");
  out.line(1, "end part");
  write_text_atomically(path, out.text);
}

void write_mbsim_h5(const Sid& sid, const std::string& path) {
  const BodyIntegrals b = body_integrals(sid);
  const Eigen::Index nq = sid.nq();
  AtomicOutput out(path);
  {
    h5::Writer w(out.temp_path());
    // MBSim's names, all at the root, no attributes (units would be unknown there)
    w.scalar("/mass", b.m, "");
    w.vector("/position integral", b.rdm, "");
    w.matrix("/position position integral", symmetrized(b.rrdm), "");  // MBSim checks symmetry to 1e-13
    w.matrix("/shape function integral", b.Pdm, "");
    Eigen::MatrixXd rPdm(9, nq);  // row 3k + a: int c_k Phi_a dm
    for (int k = 0; k < 3; ++k) rPdm.middleRows(3 * k, 3) = b.rPdm[std::size_t(k)];
    w.matrix("/position shape function integral", rPdm, "");
    Eigen::MatrixXd PPdm(6 * nq, nq);  // blocks 00 01 02 11 12 22 of int Phi_k^T Phi_l dm
    int block = 0;
    for (int k = 0; k < 3; ++k)
      for (int l = k; l < 3; ++l) PPdm.middleRows(nq * block++, nq) = b.PPdm[std::size_t(k)][std::size_t(l)];
    w.matrix("/shape function shape function integral", PPdm, "");
    w.matrix("/stiffness matrix", symmetrized(sid.Ke.M0), "");
    w.matrix("/damping matrix", symmetrized(sid.De.M0), "");
    if (!sid.nodes.empty()) {
      const auto nn = Eigen::Index(sid.nodes.size());
      Eigen::VectorXd position(3 * nn);
      Eigen::MatrixXd phi(3 * nn, nq), psi(3 * nn, nq);
      for (Eigen::Index n = 0; n < nn; ++n) {
        const Node& node = sid.nodes[std::size_t(n)];
        position.segment(3 * n, 3) = node.origin.M0.col(0);
        phi.middleRows(3 * n, 3) = node.phi;
        psi.middleRows(3 * n, 3) = node.psi;
      }
      w.vector("/nodal relative position", position, "");
      w.matrix("/nodal shape matrix of translation", phi, "");
      w.matrix("/nodal shape matrix of rotation", psi, "");
    }
    w.close();
  }
  out.commit();
}

}  // namespace isosid::format
