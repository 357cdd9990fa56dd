// Thin RAII layer over the HDF5 C API: typed dataset and attribute I/O with Eigen,
// row-major on disk, and every failure turned into an InputError naming file and dataset.
#pragma once
#include <Eigen/Dense>
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace isosid::format::h5 {

/// The most data a readable file of `file_bytes` can hold, bytes: deflate shrinks data at most
/// about 1000-fold (1100 with room), plus 1 MiB for small files.
long double most_data_bytes(std::uintmax_t file_bytes);

/// Owns one HDF5 identifier and closes it with the matching H5*close.
class Handle {
public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept;
  ~Handle() { reset(); }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset();
  /// Gives up ownership without closing; returns the identifier.
  hid_t release() {
    const hid_t id = id_;
    id_ = -1;
    return id;
  }

private:
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

class Writer {
public:
  /// Creates (truncates) the file at `path`.
  explicit Writer(const std::string& path);
  void group(const std::string& path);
  void matrix(const std::string& path, const Eigen::MatrixXd& value, const std::string& units);
  void vector(const std::string& path, const Eigen::VectorXd& value, const std::string& units);
  void tensor(const std::string& path, const std::vector<Eigen::MatrixXd>& slices, const std::string& units);
  void integers(const std::string& path, const Eigen::VectorXi& value);
  void scalar(const std::string& path, double value, const std::string& units);
  void integer(const std::string& path, long long value);
  void string(const std::string& path, const std::string& value);
  void strings(const std::string& path, const std::vector<std::string>& value);
  void attribute(const std::string& object, const std::string& name, const std::string& value);
  void attribute(const std::string& object, const std::string& name, double value);
  /// Flushes and closes; throws if HDF5 reports a failure.
  void close();

private:
  void write_doubles(const std::string& path, const std::vector<hsize_t>& dims, const double* data,
                     const std::string& units);
  [[noreturn]] void fail(const std::string& path, const std::string& what) const;
  std::string path_;
  Handle file_;
};

class Reader {
public:
  /// Opens `path` read-only; refuses files that are missing, not HDF5, or truncated.
  explicit Reader(const std::string& path);
  const std::string& path() const { return path_; }
  bool exists(const std::string& object) const;
  std::vector<std::string> children(const std::string& group) const;
  std::vector<hsize_t> shape(const std::string& dataset) const;

  /// Numeric reads check rank, shape and that every value is finite.
  Eigen::MatrixXd matrix(const std::string& dataset) const;
  Eigen::MatrixXd matrix(const std::string& dataset, Eigen::Index rows, Eigen::Index cols) const;
  Eigen::VectorXd vector(const std::string& dataset) const;
  Eigen::VectorXd vector(const std::string& dataset, Eigen::Index size) const;
  std::vector<Eigen::MatrixXd> tensor(const std::string& dataset) const;
  Eigen::VectorXi integers(const std::string& dataset) const;
  double scalar(const std::string& dataset) const;
  long long integer(const std::string& dataset) const;
  std::string string(const std::string& dataset) const;
  std::vector<std::string> strings(const std::string& dataset) const;
  std::string string_attribute(const std::string& object, const std::string& name) const;
  double double_attribute(const std::string& object, const std::string& name) const;
  bool has_attribute(const std::string& object, const std::string& name) const;

  [[noreturn]] void fail(const std::string& object, const std::string& problem) const;

private:
  Handle open_dataset(const std::string& dataset) const;
  /// The dataset's values in its (row-major) order, into memory that is not cleared first
  Eigen::VectorXd read_doubles(const std::string& dataset, std::vector<hsize_t>& dims) const;
  /// Fails unless a dataset of this shape, `bytes` per value, could come from this file, alone
  /// and together with the datasets read before it: deflate shrinks data at most about
  /// 1000-fold, so a forged shape (or many) is caught before allocation.
  void check_fits_file(const std::string& dataset, const std::vector<hsize_t>& dims, std::size_t bytes) const;
  /// The attribute, checked to exist and to hold exactly one value.
  Handle open_single_attribute(const std::string& object, const std::string& name) const;

  std::string path_;
  std::uintmax_t file_bytes_ = 0;
  mutable long double claimed_bytes_ = 0;  ///< data read so far (checked against the file size)
  Handle file_;
};

}  // namespace isosid::format::h5
