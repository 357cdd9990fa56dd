// HDF5 I/O helpers; see hdf5_file.hpp.
#include "isosid/format/hdf5_file.hpp"

#include "isosid/format/error.hpp"
#include "isosid/format/file_kind.hpp"

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>
#include <algorithm>
#include <numeric>

namespace isosid::format::h5 {
namespace {

// HDF5 prints its error stack to stderr by default; we report errors ourselves.
void silence_hdf5() {
  static const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

Handle vlen_string_type() {
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  return Handle(t, H5Tclose);
}

/// The fixed-length string type the writer uses (null-padded, `size` bytes, at least 1): no
/// global heap, whose corrupt entries made libhdf5 read past its buffers.
Handle fixed_string_type(std::size_t size) {
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, std::max<std::size_t>(size, 1));
  H5Tset_strpad(t, H5T_STR_NULLPAD);
  H5Tset_cset(t, H5T_CSET_UTF8);
  return Handle(t, H5Tclose);
}

/// The strings laid out for a fixed-length type of the longest one's size.
std::vector<char> packed(const std::vector<std::string>& values, std::size_t& size) {
  size = 1;
  for (const auto& s : values) size = std::max(size, s.size());
  std::vector<char> out(values.size() * size, '\0');
  for (std::size_t i = 0; i < values.size(); ++i) std::copy(values[i].begin(), values[i].end(), out.begin() + std::ptrdiff_t(i * size));
  return out;
}

Handle intermediate_groups() {
  hid_t p = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(p, 1);
  return Handle(p, H5Pclose);
}

/// Creates a dataset at `path` (and any missing groups on the way); invalid on failure.
Handle create_dataset(hid_t file, const std::string& path, hid_t type, hid_t space, hid_t dcpl = H5P_DEFAULT) {
  Handle lcpl = intermediate_groups();
  return Handle(H5Dcreate2(file, path.c_str(), type, space, lcpl.get(), dcpl, H5P_DEFAULT), H5Dclose);
}

/// The creation properties of an array dataset: chunked with a Fletcher-32 checksum, which
/// libhdf5 verifies on every read, so a changed byte in the data is a read error rather than a
/// wrong number. Large datasets (Taylor M1 tensors of big bases are mostly zeros for symmetric
/// bodies) are also shuffled and deflated; readers decompress transparently. Deflate level 1:
/// after the shuffle it stores these arrays within about 1 % of level 4's size at half the
/// time, and every run writes its results this way.
Handle checksummed_layout(const std::vector<hsize_t>& dims, bool compress) {
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
  if (count == 0 || dims.empty()) return dcpl;  // nothing to protect (and no chunk can be empty)
  std::vector<hsize_t> chunk = dims;
  hsize_t inner = 1;
  for (std::size_t d = 1; d < dims.size(); ++d) inner *= dims[d];
  if (inner > (hsize_t{1} << 26)) return dcpl;  // chunks must stay below 4 GiB
  chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], (hsize_t{1} << 17) / std::max<hsize_t>(inner, 1)));
  H5Pset_chunk(dcpl.get(), int(chunk.size()), chunk.data());
  if (compress) {
    H5Pset_shuffle(dcpl.get());
    H5Pset_deflate(dcpl.get(), 1);
  }
  H5Pset_fletcher32(dcpl.get());  // last: the checksum covers the stored (filtered) bytes
  return dcpl;
}

std::string shape_text(const std::vector<hsize_t>& dims) {
  std::string s = "(";
  for (std::size_t i = 0; i < dims.size(); ++i) s += (i ? ", " : "") + std::to_string(dims[i]);
  return s + ")";
}

}  // namespace

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_;
    closer_ = other.closer_;
    other.id_ = -1;
  }
  return *this;
}

void Handle::reset() {
  if (id_ >= 0 && closer_) closer_(id_);
  id_ = -1;
}

// ---------------------------------------------------------------- Writer

Writer::Writer(const std::string& path) : path_(path) {
  silence_hdf5();
  // The file is built in memory (core driver, no backing store) and written out by close():
  // libhdf5 never meets a full disk, which made it crash at exit, and a write error is one
  // errno. (The 1.8 file format's checksummed superblock would be welcome, but libhdf5 1.10
  // hands out its in-memory image with a superblock checksum that no longer matches: measured,
  // "incorrect metadata checksum" on reading. Corrupt files are caught by the reader's checks
  // and its child-process probe instead.)
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_fapl_core(fapl.get(), std::size_t{1} << 20, 0);
  // every array dataset is chunked (for its checksum), most in one chunk: small chunk B-tree
  // nodes keep that from doubling a small SID (the default, 32, costs 1.6 KB per dataset)
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  H5Pset_istore_k(fcpl.get(), 2);
  // the root group keeps its links in creation order too (MBSim iterates it by creation order)
  H5Pset_link_creation_order(fcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
  if (f < 0) throw InputError(path, "", "cannot create HDF5 file");
  file_ = Handle(f, H5Fclose);
}

void Writer::fail(const std::string& path, const std::string& what) const {
  throw ComputationError(path_ + ": " + path + ": " + what);
}

void Writer::group(const std::string& path) {
  if (H5Lexists(file_.get(), path.c_str(), H5P_DEFAULT) > 0) return;
  Handle lcpl = intermediate_groups();
  // Track creation order so that lists (nodes, contact surfaces, ...) read back in the order written.
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  H5Pset_link_creation_order(gcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  hid_t g = H5Gcreate2(file_.get(), path.c_str(), lcpl.get(), gcpl.get(), H5P_DEFAULT);
  if (g < 0) fail(path, "cannot create group");
  H5Gclose(g);
}

void Writer::write_doubles(const std::string& path, const std::vector<hsize_t>& dims, const double* data,
                           const std::string& units) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
  Handle dcpl = checksummed_layout(dims, count >= (hsize_t{1} << 16));
  Handle ds = create_dataset(file_.get(), path, H5T_IEEE_F64LE, space.get(), dcpl.get());
  if (!ds.valid()) fail(path, "cannot create dataset");
  if (count > 0 && H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail(path, "cannot write dataset");
  ds.reset();
  if (!units.empty()) attribute(path, "units", units);
}

void Writer::matrix(const std::string& path, const Eigen::MatrixXd& value, const std::string& units) {
  const RowMatrix row_major = value;
  write_doubles(path, {hsize_t(value.rows()), hsize_t(value.cols())}, row_major.data(), units);
}

void Writer::vector(const std::string& path, const Eigen::VectorXd& value, const std::string& units) {
  write_doubles(path, {hsize_t(value.size())}, value.data(), units);
}

void Writer::tensor(const std::string& path, const std::vector<Eigen::MatrixXd>& slices, const std::string& units) {
  const hsize_t rows = slices.empty() ? 0 : hsize_t(slices[0].rows());
  const hsize_t cols = slices.empty() ? 0 : hsize_t(slices[0].cols());
  std::vector<double> data;
  data.reserve(slices.size() * rows * cols);
  for (const auto& slice : slices) {
    if (hsize_t(slice.rows()) != rows || hsize_t(slice.cols()) != cols) fail(path, "slices differ in shape");
    const RowMatrix row_major = slice;
    data.insert(data.end(), row_major.data(), row_major.data() + row_major.size());
  }
  write_doubles(path, {hsize_t(slices.size()), rows, cols}, data.data(), units);
}

void Writer::integers(const std::string& path, const Eigen::VectorXi& value) {
  const hsize_t dims[1] = {hsize_t(value.size())};
  Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose);
  Handle dcpl = checksummed_layout({dims[0]}, false);
  Handle ds = create_dataset(file_.get(), path, H5T_STD_I32LE, space.get(), dcpl.get());
  if (!ds.valid()) fail(path, "cannot create dataset");
  if (value.size() > 0 && H5Dwrite(ds.get(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.data()) < 0)
    fail(path, "cannot write dataset");
}

void Writer::scalar(const std::string& path, double value, const std::string& units) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle ds = create_dataset(file_.get(), path, H5T_IEEE_F64LE, space.get());
  if (!ds.valid() || H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) < 0)
    fail(path, "cannot write scalar");
  ds.reset();
  if (!units.empty()) attribute(path, "units", units);
}

void Writer::integer(const std::string& path, long long value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle ds = create_dataset(file_.get(), path, H5T_STD_I64LE, space.get());
  if (!ds.valid() || H5Dwrite(ds.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) < 0)
    fail(path, "cannot write integer");
}

void Writer::string(const std::string& path, const std::string& value) {
  std::size_t size = 0;
  const std::vector<char> text = packed({value}, size);
  Handle type = fixed_string_type(size);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle ds = create_dataset(file_.get(), path, type.get(), space.get());
  if (!ds.valid() || H5Dwrite(ds.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0)
    fail(path, "cannot write string");
}

void Writer::strings(const std::string& path, const std::vector<std::string>& value) {
  std::size_t size = 0;
  const std::vector<char> text = packed(value, size);
  Handle type = fixed_string_type(size);
  const hsize_t dims[1] = {hsize_t(value.size())};
  Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose);
  Handle ds = create_dataset(file_.get(), path, type.get(), space.get());
  if (!ds.valid()) fail(path, "cannot create string list");
  if (!value.empty() && H5Dwrite(ds.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0)
    fail(path, "cannot write string list");
}

void Writer::attribute(const std::string& object, const std::string& name, const std::string& value) {
  std::size_t size = 0;
  const std::vector<char> text = packed({value}, size);
  Handle type = fixed_string_type(size);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate_by_name(file_.get(), object.c_str(), name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                                H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose);
  if (!attr.valid() || H5Awrite(attr.get(), type.get(), text.data()) < 0) fail(object, "cannot write attribute " + name);
}

void Writer::attribute(const std::string& object, const std::string& name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate_by_name(file_.get(), object.c_str(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose);
  if (!attr.valid() || H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail(object, "cannot write attribute " + name);
}

void Writer::close() {
  if (!file_.valid()) return;
  if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) fail("/", "cannot flush file");
  const ssize_t size = H5Fget_file_image(file_.get(), nullptr, 0);
  if (size < 0) fail("/", "cannot take the file image");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(file_.get(), image.data(), image.size()) != size) fail("/", "cannot take the file image");
  if (H5Fclose(file_.release()) < 0) fail("/", "cannot close file");
  const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw ComputationError(path_ + ": cannot create: " + std::strerror(errno));
  for (std::size_t done = 0; done < image.size();) {
    const ssize_t n = ::write(fd, image.data() + done, image.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      ::close(fd);
      throw ComputationError(path_ + ": cannot write " + std::to_string(image.size()) + " bytes: " + std::strerror(error));
    }
    done += std::size_t(n);
  }
  if (::close(fd) != 0) throw ComputationError(path_ + ": cannot write: " + std::strerror(errno));
}

// ---------------------------------------------------------------- Reader

Reader::Reader(const std::string& path) : path_(path) {
  silence_hdf5();
  require_input_file(path);
  std::error_code ec;
  const htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
  if (is_hdf5 <= 0) throw InputError(path, "", "not an HDF5 file");
  file_bytes_ = std::filesystem::file_size(path, ec);
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw InputError(path, "", "cannot be opened: truncated or corrupt HDF5 file");
  file_ = Handle(f, H5Fclose);
}

void Reader::fail(const std::string& object, const std::string& problem) const {
  throw InputError(path_, object, problem);
}

long double most_data_bytes(std::uintmax_t file_bytes) {
  return 1100.0L * static_cast<long double>(file_bytes) + (1 << 20);
}

void Reader::check_fits_file(const std::string& dataset, const std::vector<hsize_t>& dims, std::size_t bytes) const {
  long double count = 1;
  for (const hsize_t d : dims) count *= static_cast<long double>(d);
  const long double most = most_data_bytes(file_bytes_);
  const long double claimed = count * static_cast<long double>(bytes);
  if (claimed > most)
    fail(dataset, "declares shape " + shape_text(dims) + ", more data than a file of " + std::to_string(file_bytes_) +
                      " bytes can hold (corrupt file)");
  claimed_bytes_ += claimed;
  if (claimed_bytes_ > most)
    fail(dataset, "declares shape " + shape_text(dims) + ": with the datasets before it, more data than a file of " +
                      std::to_string(file_bytes_) + " bytes can hold (corrupt file)");
}

bool Reader::exists(const std::string& object) const {
  // H5Lexists needs every intermediate link to exist, so walk the path.
  std::string partial;
  std::size_t start = 1;
  while (start <= object.size()) {
    const std::size_t slash = object.find('/', start);
    partial = object.substr(0, slash);
    if (H5Lexists(file_.get(), partial.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return true;
}

std::vector<std::string> Reader::children(const std::string& group) const {
  std::vector<std::string> names;
  if (!exists(group)) return names;
  Handle g(H5Gopen2(file_.get(), group.c_str(), H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail(group, "is not a group");
  H5G_info_t info;
  if (H5Gget_info(g.get(), &info) < 0) fail(group, "cannot be listed (corrupt file)");
  // Creation order where the writer tracked it, else alphabetical.
  const H5_index_t index =
      H5Lget_name_by_idx(g.get(), ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, 0, nullptr, 0, H5P_DEFAULT) >= 0
          ? H5_INDEX_CRT_ORDER
          : H5_INDEX_NAME;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t n = H5Lget_name_by_idx(g.get(), ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (n < 0) fail(group, "cannot be listed (corrupt file)");
    std::string name(static_cast<std::size_t>(n), '\0');
    H5Lget_name_by_idx(g.get(), ".", index, H5_ITER_INC, i, name.data(), name.size() + 1, H5P_DEFAULT);
    names.push_back(name);
  }
  return names;
}

Handle Reader::open_dataset(const std::string& dataset) const {
  if (!exists(dataset)) fail(dataset, "missing");
  Handle ds(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) fail(dataset, "is not a readable dataset (corrupt file?)");
  return ds;
}

std::vector<hsize_t> Reader::shape(const std::string& dataset) const {
  Handle ds = open_dataset(dataset);
  Handle space(H5Dget_space(ds.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail(dataset, "has an unreadable shape (corrupt file?)");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

Eigen::VectorXd Reader::read_doubles(const std::string& dataset, std::vector<hsize_t>& dims) const {
  dims = shape(dataset);
  Handle ds = open_dataset(dataset);
  Handle type(H5Dget_type(ds.get()), H5Tclose);
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (type_class != H5T_FLOAT && type_class != H5T_INTEGER) fail(dataset, "is not numeric");
  check_fits_file(dataset, dims, sizeof(double));
  const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
  Eigen::VectorXd data(static_cast<Eigen::Index>(count));  // not cleared: H5Dread writes every value
  if (count > 0 && H5Dread(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    fail(dataset, "cannot be read (truncated or corrupt file)");
  for (Eigen::Index i = 0; i < data.size(); ++i)
    if (!std::isfinite(data(i))) fail(dataset, "non-finite value (" + std::to_string(data(i)) + ") at flat index " + std::to_string(i));
  return data;
}

Eigen::MatrixXd Reader::matrix(const std::string& dataset) const {
  std::vector<hsize_t> dims;
  Eigen::VectorXd data = read_doubles(dataset, dims);
  if (dims.size() != 2) fail(dataset, "expected a matrix, found shape " + shape_text(dims));
  return Eigen::Map<RowMatrix>(data.data(), Eigen::Index(dims[0]), Eigen::Index(dims[1]));
}

Eigen::MatrixXd Reader::matrix(const std::string& dataset, Eigen::Index rows, Eigen::Index cols) const {
  Eigen::MatrixXd m = matrix(dataset);
  if (m.rows() != rows || m.cols() != cols)
    fail(dataset, "wrong shape (" + std::to_string(m.rows()) + ", " + std::to_string(m.cols()) + "), expected (" +
                      std::to_string(rows) + ", " + std::to_string(cols) + ")");
  return m;
}

Eigen::VectorXd Reader::vector(const std::string& dataset) const {
  std::vector<hsize_t> dims;
  Eigen::VectorXd data = read_doubles(dataset, dims);
  if (dims.size() != 1) fail(dataset, "expected a vector, found shape " + shape_text(dims));
  return data;
}

Eigen::VectorXd Reader::vector(const std::string& dataset, Eigen::Index size) const {
  Eigen::VectorXd v = vector(dataset);
  if (v.size() != size)
    fail(dataset, "wrong length " + std::to_string(v.size()) + ", expected " + std::to_string(size));
  return v;
}

std::vector<Eigen::MatrixXd> Reader::tensor(const std::string& dataset) const {
  std::vector<hsize_t> dims;
  Eigen::VectorXd data = read_doubles(dataset, dims);
  if (dims.size() != 3) fail(dataset, "expected a rank-3 array, found shape " + shape_text(dims));
  std::vector<Eigen::MatrixXd> slices;
  const std::size_t block = dims[1] * dims[2];
  for (hsize_t k = 0; k < dims[0]; ++k)
    slices.emplace_back(Eigen::Map<RowMatrix>(data.data() + k * block, Eigen::Index(dims[1]), Eigen::Index(dims[2])));
  return slices;
}

Eigen::VectorXi Reader::integers(const std::string& dataset) const {
  Handle ds = open_dataset(dataset);
  std::vector<hsize_t> dims = shape(dataset);
  if (dims.size() != 1) fail(dataset, "expected an integer vector, found shape " + shape_text(dims));
  Handle type(H5Dget_type(ds.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_INTEGER) fail(dataset, "is not an integer dataset");
  check_fits_file(dataset, dims, sizeof(int));
  Eigen::VectorXi v(static_cast<Eigen::Index>(dims[0]));
  if (v.size() > 0 && H5Dread(ds.get(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    fail(dataset, "cannot be read (truncated or corrupt file)");
  return v;
}

double Reader::scalar(const std::string& dataset) const {
  std::vector<hsize_t> dims;
  Eigen::VectorXd data = read_doubles(dataset, dims);
  if (!dims.empty()) fail(dataset, "expected a scalar, found shape " + shape_text(dims));
  return data(0);
}

long long Reader::integer(const std::string& dataset) const {
  Handle ds = open_dataset(dataset);
  if (!shape(dataset).empty()) fail(dataset, "expected a scalar");
  Handle type(H5Dget_type(ds.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_INTEGER) fail(dataset, "is not an integer");
  long long value = 0;
  if (H5Dread(ds.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) < 0)
    fail(dataset, "cannot be read (truncated or corrupt file)");
  return value;
}

namespace {
// Reads `count` strings from a dataset or attribute whose type is `file_type`.
template <class ReadFn>
std::vector<std::string> read_string_values(hid_t file_type, std::size_t count, ReadFn read, bool& ok) {
  std::vector<std::string> out;
  ok = true;
  if (H5Tget_class(file_type) != H5T_STRING) {
    ok = false;
    return out;
  }
  if (H5Tis_variable_str(file_type) > 0) {
    Handle mem = vlen_string_type();
    std::vector<char*> raw(count, nullptr);
    if (count > 0 && read(mem.get(), raw.data()) < 0) {
      ok = false;
      return out;
    }
    for (char* s : raw) {
      out.emplace_back(s ? s : "");
      H5free_memory(s);
    }
  } else {
    const std::size_t size = H5Tget_size(file_type);
    Handle mem(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(mem.get(), size);
    H5Tset_strpad(mem.get(), H5T_STR_NULLPAD);       // the bytes as stored, cut at the first NUL below
    H5Tset_cset(mem.get(), H5Tget_cset(file_type));  // no conversion between ASCII and UTF-8
    std::vector<char> raw(count * size + 1, '\0');
    if (count > 0 && read(mem.get(), raw.data()) < 0) {
      ok = false;
      return out;
    }
    for (std::size_t i = 0; i < count; ++i) {
      std::string s(raw.data() + i * size, size);
      out.push_back(s.substr(0, s.find('\0')));
    }
  }
  return out;
}
}  // namespace

std::vector<std::string> Reader::strings(const std::string& dataset) const {
  Handle ds = open_dataset(dataset);
  std::vector<hsize_t> dims = shape(dataset);
  if (dims.size() > 1) fail(dataset, "expected a list of strings, found shape " + shape_text(dims));
  const std::size_t count = dims.empty() ? 1 : dims[0];
  Handle type(H5Dget_type(ds.get()), H5Tclose);
  if (!type.valid()) fail(dataset, "is not a readable string dataset");
  // fixed-length strings occupy their declared size each: a corrupt size must not be allocated
  const bool fixed_length = H5Tis_variable_str(type.get()) <= 0;
  check_fits_file(dataset, dims, fixed_length ? std::max<std::size_t>(1, H5Tget_size(type.get())) : 1);
  bool ok = true;
  auto out = read_string_values(type.get(), count,
                                [&](hid_t mem, void* buf) { return H5Dread(ds.get(), mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf); },
                                ok);
  if (!ok) fail(dataset, "is not a readable string dataset");
  return out;
}

std::string Reader::string(const std::string& dataset) const {
  if (!shape(dataset).empty()) fail(dataset, "expected a single string");
  return strings(dataset).at(0);
}

bool Reader::has_attribute(const std::string& object, const std::string& name) const {
  return exists(object) && H5Aexists_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

Handle Reader::open_single_attribute(const std::string& object, const std::string& name) const {
  if (!has_attribute(object, name)) fail(object, "missing attribute '" + name + "'");
  Handle attr(H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) fail(object, "attribute '" + name + "' cannot be opened (corrupt file)");
  // one value is read into room for one: a corrupt dataspace must not make H5Aread write more
  Handle space(H5Aget_space(attr.get()), H5Sclose);
  if (!space.valid() || H5Sget_simple_extent_npoints(space.get()) != 1)
    fail(object, "attribute '" + name + "' must hold exactly one value");
  return attr;
}

std::string Reader::string_attribute(const std::string& object, const std::string& name) const {
  Handle attr = open_single_attribute(object, name);
  Handle type(H5Aget_type(attr.get()), H5Tclose);
  // an attribute lives uncompressed in its object header, so it cannot be longer than the file
  if (type.valid() && H5Tis_variable_str(type.get()) <= 0 && H5Tget_size(type.get()) > file_bytes_)
    fail(object, "attribute '" + name + "' declares a string longer than the file (corrupt file)");
  bool ok = type.valid();
  std::vector<std::string> out;
  if (ok) out = read_string_values(type.get(), 1, [&](hid_t mem, void* buf) { return H5Aread(attr.get(), mem, buf); }, ok);
  if (!ok || out.empty()) fail(object, "attribute '" + name + "' is not a readable string");
  return out[0];
}

double Reader::double_attribute(const std::string& object, const std::string& name) const {
  Handle attr = open_single_attribute(object, name);
  double value = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail(object, "attribute '" + name + "' is not numeric");
  if (!std::isfinite(value)) fail(object, "attribute '" + name + "' is not finite");
  return value;
}

}  // namespace isosid::format::h5
