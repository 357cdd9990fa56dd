// ParaView frames of a run; see paraview_series.hpp.
#include "output/paraview_series.hpp"

#include "output/stress_monitor.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/visual_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace isosid::run {
namespace {
namespace vtk = format::vtk;

/// Frames of a run whose scene sets no paraview_interval: enough to follow a wave or a
/// contact, few enough to stay in the tens of megabytes.
constexpr double kDefaultFrames = 200;

}  // namespace

ParaviewSeries::ParaviewSeries(const MultibodySystem& system, const Scene& scene, std::string results_dir)
    : system_(system),
      dir_((std::filesystem::path(std::move(results_dir)) / "paraview").string()),
      interval_(frame_interval(scene)) {
  for (const auto& b : system.bodies()) {
    const BodySpec* spec = scene.body(b->name());
    if (spec && spec->rigid) continue;
    if (!b->sid().visual)
      throw format::InputError(scene.file, "output.paraview",
                               "the SID of '" + b->name() + "' has no viewing mesh: add [visual] to its model file");
    bodies_.push_back({b.get(), &*b->sid().visual, format::visual_grid(*b->sid().visual), "body_" + vtk::file_safe(b->name()),
                       b->sid().material.poisson_ratio});
  }
  for (const SurfaceContact& c : system.contacts()) contact_stems_.push_back("contact_" + vtk::file_safe(c.name()));
}

double ParaviewSeries::frame_interval(const Scene& scene) {
  return scene.output.paraview_interval > 0 ? scene.output.paraview_interval
                                            : std::max(scene.simulation.output_interval, scene.simulation.end_time / kDefaultFrames);
}

void ParaviewSeries::sample(double t, const double* y) {
  if (t < next_time_ * (1 - 1e-9)) return;
  try {
    if (frames_ == 0) std::filesystem::create_directories(dir_);  // RunFolder::start removed an earlier run's
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%05d.vtu", frames_);
    int part = 0;
    for (BodyView& view : bodies_) {
      const std::string file = view.file_stem + suffix;
      write_body(view, y, (std::filesystem::path(dir_) / file).string());
      entries_.push_back({t, part++, view.body->name(), file});
    }
    for (std::size_t k = 0; k < contact_stems_.size(); ++k) {
      const std::string file = contact_stems_[k] + suffix;
      write_contact(system_.contacts()[k], y, (std::filesystem::path(dir_) / file).string());
      entries_.push_back({t, part++, system_.contacts()[k].name(), file});
    }
  } catch (const format::ComputationError&) {
    throw;
  } catch (const std::exception& e) {  // a full disk, a folder gone: the run fails here and keeps its results
    throw format::ComputationError("ParaView frame at t = " + std::to_string(t) + " s: " + e.what());
  }
  ++frames_;
  next_time_ = (std::floor(t / interval_ + 1e-9) + 1) * interval_;  // the next multiple of the interval
}

void ParaviewSeries::write_body(BodyView& view, const double* y, const std::string& file) const {
  const FloatingBody& body = *view.body;
  const format::VisualMesh& mesh = *view.mesh;
  const int dim = body.sid().dim();
  const Eigen::Index n = mesh.points();
  const Eigen::Matrix3d A = body.orientation(y).toRotationMatrix();
  const Eigen::Vector3d r = body.r(y);
  const Eigen::VectorXd u = mesh.Phi * body.q(y);
  std::vector<double> displacement(std::size_t(3 * n)), velocity(std::size_t(3 * n));
  Eigen::Vector3d X = Eigen::Vector3d::Zero(), du = Eigen::Vector3d::Zero();
  for (Eigen::Index p = 0; p < n; ++p) {
    X.head(dim) = mesh.position.row(p).transpose();
    du.head(dim) = u.segment(p * dim, dim);
    const Eigen::Vector3d x = X + du;
    view.grid.points.row(p) = (r + A * x).transpose();
    const Eigen::Vector3d world_u = A * du, world_v = body.point_velocity(x, mesh.Phi.middleRows(p * dim, dim), y);
    for (int a = 0; a < 3; ++a) displacement[std::size_t(3 * p + a)] = world_u(a), velocity[std::size_t(3 * p + a)] = world_v(a);
  }
  view.grid.point_data = {{"displacement", 3, std::move(displacement)}, {"velocity", 3, std::move(velocity)}};
  if (!mesh.stress_components.empty()) {
    const Eigen::VectorXd sigma = mesh.S * body.q(y);
    const auto nc = Eigen::Index(mesh.stress_components.size());
    std::vector<double> mises(static_cast<std::size_t>(n));
    for (Eigen::Index p = 0; p < n; ++p)
      mises[std::size_t(p)] = von_mises(mesh.stress_components, sigma.data() + p * nc, body.sid().analysis, view.poisson_ratio);
    view.grid.point_data.push_back({"von_mises", 1, std::move(mises)});
  }
  vtk::write_vtu(file, view.grid);
}

void ParaviewSeries::write_contact(const SurfaceContact& contact, const double* y, const std::string& file) const {
  const std::vector<PointLoad> loads = contact.point_loads(y);
  vtk::UnstructuredGrid grid;
  grid.points.resize(Eigen::Index(loads.size()), 3);
  vtk::PointArray force{"force", 3, {}}, pressure{"pressure", 1, {}}, gap{"gap", 1, {}};
  for (std::size_t i = 0; i < loads.size(); ++i) {
    grid.points.row(Eigen::Index(i)) = loads[i].position.transpose();
    force.values.insert(force.values.end(), loads[i].force.data(), loads[i].force.data() + 3);
    pressure.values.push_back(loads[i].pressure);
    gap.values.push_back(loads[i].gap);
    grid.connectivity.push_back(std::int64_t(i));
    grid.offsets.push_back(std::int64_t(i + 1));
    grid.types.push_back(vtk::Vertex);
  }
  grid.point_data = {std::move(force), std::move(pressure), std::move(gap)};
  vtk::write_vtu(file, grid);
}

std::string ParaviewSeries::write_collection() const { return write_collection(dir_, entries_); }

std::string ParaviewSeries::write_collection(const std::string& dir, const std::vector<vtk::CollectionEntry>& entries) {
  const std::string path = (std::filesystem::path(dir) / "scene.pvd").string();
  try {
    std::filesystem::create_directories(dir);
    // a collection never lists a frame that is not there (removed while the run wrote)
    for (const vtk::CollectionEntry& e : entries)
      if (!std::filesystem::exists(std::filesystem::path(dir) / e.file))
        throw format::ComputationError("frame " + e.file + " is missing: removed while the run wrote");
    vtk::write_pvd(path, entries);
  } catch (const std::exception& e) {
    throw format::ComputationError("ParaView collection " + path + ": " + e.what());
  }
  return path;
}

}  // namespace isosid::run
