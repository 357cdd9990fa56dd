// ParaView output of a run ([output] paraview = true): at every frame time, each flexible
// body's viewing mesh (the SID's /visual) moved to its deformed world position, with the
// displacement, velocity and von Mises stress of every point, and each contact's loaded
// points with their forces; paraview/scene.pvd lists the frames as one time series with one
// part per body and contact. Rigid bodies and fixed surfaces are not drawn.
#pragma once
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"
#include "solve/simulation.hpp"

#include "isosid/format/vtk_xml.hpp"

#include <string>
#include <vector>

namespace isosid::run {

/// An observer of the run: after the recorder in an ObserverList (whose sample sets the
/// quasistatic coordinates of y that the frames draw).
class ParaviewSeries : public SimulationObserver {
public:
  /// Refuses (InputError on the scene's [output].paraview) a flexible body whose SID has no
  /// viewing mesh. Writes nothing yet.
  ParaviewSeries(const MultibodySystem& system, const Scene& scene, std::string results_dir);
  /// s between the frames of `scene`: its paraview_interval, or its output interval but at
  /// most 200 frames.
  static double frame_interval(const Scene& scene);

  /// Writes a frame at the first sample at or after each frame time (the system's
  /// quasistatic coordinates must be those of y, as after MultibodySystem::contact_states).
  void sample(double t, const double* y) override;
  void step(double, const double*) override {}
  void contact_event(int, bool, double) override {}
  /// Writes paraview/scene.pvd listing the frames written so far (also after a failed or
  /// interrupted run) and returns its path.
  std::string write_collection() const;
  /// Writes `dir`/scene.pvd listing `entries` (their files relative to dir) and returns its
  /// path; a failure to write is a ComputationError naming it.
  static std::string write_collection(const std::string& dir, const std::vector<format::vtk::CollectionEntry>& entries);
  int frames() const { return frames_; }
  /// The frames' files so far, relative to results_dir/paraview (what write_collection lists).
  const std::vector<format::vtk::CollectionEntry>& entries() const { return entries_; }

private:
  struct BodyView {
    const FloatingBody* body;
    const format::VisualMesh* mesh;
    format::vtk::UnstructuredGrid grid;  ///< cells and point arrays, rewritten each frame
    std::string file_stem;
    double poisson_ratio;                ///< for the out-of-plane stress of plane strain
  };
  void write_body(BodyView& view, const double* y, const std::string& file) const;
  void write_contact(const SurfaceContact& contact, const double* y, const std::string& file) const;

  const MultibodySystem& system_;
  std::string dir_;       ///< results_dir/paraview
  double interval_;
  double next_time_ = 0;  ///< the next frame's time
  int frames_ = 0;
  std::vector<BodyView> bodies_;
  std::vector<std::string> contact_stems_;
  std::vector<format::vtk::CollectionEntry> entries_;
};

}  // namespace isosid::run
