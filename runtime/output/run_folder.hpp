// The results folder of an isosid-run belongs to one run at a time. It is checked before any
// work (a file, or a path that cannot become a folder, is no results folder; none of the
// scene's inputs may be among what the run replaces there), locked while the run writes it
// (flock on a lock file in it, released when the process ends, also by a crash), and cleared
// of an earlier run's outputs when the run starts.
#pragma once
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace isosid::run {

class RunFolder {
public:
  /// What isosid-run writes into a results folder, and so removes there when a run starts:
  /// results.h5, summary.json, paraview/, phases/.
  static const std::vector<std::string>& outputs();
  /// The lock file taken by the run that writes the folder (it stays when the run ends).
  static constexpr const char* kLockFile = ".isosid-run.lock";

  /// Refuses (InputError on -o) a `dir` that is not a folder and cannot be created as one, a
  /// folder that is not writable, one where the run would replace or remove an input of
  /// `scene` (its scene file, SIDs, models or model cache), and one whose results.h5 or
  /// summary.json is no regular file (a FIFO, say). If the folder exists, takes its
  /// lock now: a folder that another isosid-run writes is refused before any work.
  RunFolder(std::string dir, const Scene& scene);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  const std::string& path() const { return dir_; }
  /// Creates the folder, takes its lock unless held, removes an earlier run's outputs and
  /// writes summary.json with status "running" (so that an earlier run's "completed" cannot
  /// outlive a crash of this one). Called once the scene, its SIDs and monitors are accepted.
  void start(const std::string& scene_file);

private:
  /// Takes the folder's lock or refuses: "DIR: another isosid-run (pid N) is writing there".
  void lock();

  std::string dir_;
  int lock_fd_ = -1;
};

}  // namespace isosid::run
