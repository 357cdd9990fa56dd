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

void replace_dataset(const std::string& file, const std::string& dataset, const Eigen::MatrixXd& value) {
  remove_object(file, dataset);
  const hid_t f = open_rw(file);
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rm = value;
  const hsize_t dims[2] = {hsize_t(value.rows()), hsize_t(value.cols())};
  const hid_t space = H5Screate_simple(2, dims, nullptr);
  const hid_t ds = H5Dcreate2(f, dataset.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rm.data());
  H5Dclose(ds);
  H5Sclose(space);
  H5Fclose(f);
}

namespace {
void replace_with_scalar(const std::string& file, const std::string& dataset, hid_t file_type, hid_t mem_type,
                         const void* value) {
  remove_object(file, dataset);
  const hid_t f = open_rw(file);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t ds = H5Dcreate2(f, dataset.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value);
  H5Dclose(ds);
  H5Sclose(space);
  H5Fclose(f);
}
}  // namespace

void replace_integer(const std::string& file, const std::string& dataset, long long value) {
  replace_with_scalar(file, dataset, H5T_STD_I64LE, H5T_NATIVE_LLONG, &value);
}

void replace_scalar(const std::string& file, const std::string& dataset, double value) {
  replace_with_scalar(file, dataset, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void truncate_copy(const std::string& file, const std::string& target, double fraction) {
  std::ifstream in(file, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream out(target, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(double(bytes.size()) * fraction));
}

}  // namespace isosid::test
