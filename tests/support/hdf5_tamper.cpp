// Direct HDF5 edits for negative tests; see hdf5_tamper.hpp.
#include "support/hdf5_tamper.hpp"

#include <filesystem>
#include <fstream>
#include <hdf5.h>
#include <stdexcept>
#include <vector>

namespace isosid::test {
namespace {
hid_t open_rw(const std::string& file) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("cannot open " + file);
  return f;
}
}  // namespace

void remove_object(const std::string& file, const std::string& object) {
  const hid_t f = open_rw(file);
  const herr_t rc = H5Ldelete(f, object.c_str(), H5P_DEFAULT);
  H5Fclose(f);
  if (rc < 0) throw std::runtime_error("cannot delete " + object);
}

namespace {
/// Replaces `dataset` by one of dataspace `space` (closed here) holding `data`.
void replace_with(const std::string& file, const std::string& dataset, hid_t space, hid_t file_type, hid_t mem_type,
                  const void* data) {
  remove_object(file, dataset);
  const hid_t f = open_rw(file);
  const hid_t ds = H5Dcreate2(f, dataset.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  H5Dclose(ds);
  H5Sclose(space);
  H5Fclose(f);
}
}  // namespace

void replace_dataset(const std::string& file, const std::string& dataset, const Eigen::MatrixXd& value) {
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rm = value;
  const hsize_t dims[2] = {hsize_t(value.rows()), hsize_t(value.cols())};
  replace_with(file, dataset, H5Screate_simple(2, dims, nullptr), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, rm.data());
}

void replace_integers(const std::string& file, const std::string& dataset, const Eigen::VectorXi& value) {
  const hsize_t dims[1] = {hsize_t(value.size())};
  replace_with(file, dataset, H5Screate_simple(1, dims, nullptr), H5T_STD_I32LE, H5T_NATIVE_INT, value.data());
}

void replace_integer(const std::string& file, const std::string& dataset, long long value) {
  replace_with(file, dataset, H5Screate(H5S_SCALAR), H5T_STD_I64LE, H5T_NATIVE_LLONG, &value);
}

void replace_scalar(const std::string& file, const std::string& dataset, double value) {
  replace_with(file, dataset, H5Screate(H5S_SCALAR), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

namespace {
void set_attribute_bytes(const std::string& file, const std::string& object, const std::string& name, hid_t file_type,
                         hid_t mem_type, const void* value) {
  const hid_t f = open_rw(file);
  if (H5Aexists_by_name(f, object.c_str(), name.c_str(), H5P_DEFAULT) > 0)
    H5Adelete_by_name(f, object.c_str(), name.c_str(), H5P_DEFAULT);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate_by_name(f, object.c_str(), name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, mem_type, value);
  H5Aclose(a);
  H5Sclose(space);
  H5Fclose(f);
}
}  // namespace

void set_attribute(const std::string& file, const std::string& object, const std::string& name, double value) {
  set_attribute_bytes(file, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void set_attribute(const std::string& file, const std::string& object, const std::string& name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() + 1);
  set_attribute_bytes(file, object, name, type, type, value.c_str());
  H5Tclose(type);
}

void flip_stored_data_bit(const std::string& file, const std::string& dataset) {
  haddr_t address = HADDR_UNDEF;
  {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t ds = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    address = H5Dget_offset(ds);  // contiguous data
    if (address == HADDR_UNDEF) {  // chunked: its first chunk
      const hid_t space = H5Dget_space(ds);
      hsize_t offset[3] = {0, 0, 0}, size = 0;
      unsigned mask = 0;
      H5Dget_chunk_info(ds, space, 0, offset, &mask, &address, &size);
      H5Sclose(space);
    }
    H5Dclose(ds);
    H5Fclose(f);
  }
  if (address == HADDR_UNDEF) throw std::runtime_error(dataset + ": no stored data to damage");
  std::fstream io(file, std::ios::binary | std::ios::in | std::ios::out);
  io.seekg(std::streamoff(address) + 3);
  char byte = 0;
  io.read(&byte, 1);
  byte ^= 1;
  io.seekp(std::streamoff(address) + 3);
  io.write(&byte, 1);
}

void truncate_copy(const std::string& file, const std::string& target, double fraction) {
  std::ifstream in(file, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream out(target, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(double(bytes.size()) * fraction));
}

}  // namespace isosid::test
