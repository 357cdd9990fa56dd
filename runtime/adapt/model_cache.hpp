// The SIDs the adaptive loop asks for ([R2] Sect. 4, Fig. 2, docs/references.md): a body's coarse
// model and its fine models, refined hierarchically around an impact point, built by isosid-prep as
// a subprocess and kept in a cache directory under the hash of their request. A request that
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
  double width = 0;           ///< m
  double contact_radius = 0;  ///< m; > 0: the model's [contact_resolution] sized for it (isosid-prep --contact-radius)
};

/// One fine model of a batch: the body's model file and where it is refined.
struct FineRequest {
  std::string model_file;
  RefinementRequest request;
};

/// A SID the cache holds.
struct CachedSid {
  std::string file;
  bool hit = false;      ///< found in the cache (or built for an equal request of its batch): no preprocessing ran
  double seconds = 0;    ///< wall time from its isosid-prep's start to its SID (0 on a hit; builds side by side overlap)
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
  /// The same for several requests (an impact's two bodies), in order. The missing ones are
  /// built side by side, one isosid-prep per core, each with its share of the cores for its
  /// parallel assembly: the rest of isosid-prep runs on one thread. A refusal or failure is
  /// thrown once every build started has ended.
  std::vector<CachedSid> fine(const std::vector<FineRequest>& requests);

  int hits() const { return hits_; }
  int builds() const { return builds_; }

private:
  /// What isosid-prep is asked for: `options` on `model_file` (`what` says why, in its progress line).
  struct Request {
    std::string model_file;
    std::vector<std::string> options;
    std::string what;
  };
  /// The SIDs of the requests: from the cache, or built into it, side by side.
  std::vector<CachedSid> lookup(const std::vector<Request>& requests);
  /// Where the cache keeps the SID of a request.
  std::string cached_file(const Request& request) const;

  std::string directory_;
  bool quiet_;
  int hits_ = 0, builds_ = 0;
};

}  // namespace isosid::run
