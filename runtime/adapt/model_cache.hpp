// The SIDs the adaptive loop asks for (seed 001 Sect. 4, Fig. 2): a body's coarse model and
// its fine models, refined hierarchically around an impact point, built by isosid-prep as a
// subprocess and kept in a cache directory under the hash of their request. A request that
// was built before (by this run, an earlier impact or an earlier run) is read, not rebuilt.
#pragma once
#include <string>
#include <vector>

namespace isosid::run {

/// Where a fine model is refined: the body's contact surface, the tangential parameter(s) of
/// the impact point on it (the touch's parameter on the surface's master patch) and the
/// physical width of the refined region (the contact interval).
struct RefinementRequest {
  std::string surface;
  std::vector<double> at;
  double width = 0;  ///< m
};

/// A SID the cache holds.
struct CachedSid {
  std::string file;
  bool hit = false;      ///< found in the cache: no preprocessing ran
  double seconds = 0;    ///< wall time of the preprocessing (0 on a hit)
};

class ModelCache {
public:
  /// `directory` is created when the first SID is built.
  ModelCache(std::string directory, bool quiet);

  /// The coarse model of a body whose model file has a [refinement.hierarchical] table
  /// (isosid-prep --coarse): globally refined, reduced to its normal modes.
  CachedSid coarse(const std::string& model_file);
  /// The model refined around the request's point (isosid-prep --refine-at --refine-width); its
  /// SID's /transfer maps states from and to coarse(model_file). A refused request (a point
  /// off the surface, a model without hierarchical refinement) throws InputError.
  CachedSid fine(const std::string& model_file, const RefinementRequest& request);

  int hits() const { return hits_; }
  int builds() const { return builds_; }

private:
  /// The SID of `model_file` built with `options`: from the cache, or built into it.
  CachedSid lookup(const std::string& model_file, const std::vector<std::string>& options, const std::string& what);

  std::string directory_;
  bool quiet_;
  int hits_ = 0, builds_ = 0;
};

}  // namespace isosid::run
