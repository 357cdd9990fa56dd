// Test support: damage a valid SID file in specific ways to exercise the reader's checks.
#pragma once
#include <Eigen/Dense>
#include <string>

namespace isosid::test {

/// Replaces a dataset by a matrix of doubles (any shape).
void replace_dataset(const std::string& file, const std::string& dataset, const Eigen::MatrixXd& value);
/// Replaces a dataset by a scalar double.
void replace_scalar(const std::string& file, const std::string& dataset, double value);
/// Replaces a dataset by a scalar 64-bit integer.
void replace_integer(const std::string& file, const std::string& dataset, long long value);
/// Replaces a dataset by a vector of 32-bit integers.
void replace_integers(const std::string& file, const std::string& dataset, const Eigen::VectorXi& value);
/// Removes a dataset or group.
void remove_object(const std::string& file, const std::string& object);
/// Sets a numeric attribute (replacing one of that name).
void set_attribute(const std::string& file, const std::string& object, const std::string& name, double value);
/// Sets a string attribute (replacing one of that name, of any type).
void set_attribute(const std::string& file, const std::string& object, const std::string& name, const std::string& value);
/// Flips the lowest bit of one byte of a dataset's stored data, in place, past libhdf5.
void flip_stored_data_bit(const std::string& file, const std::string& dataset);
/// Copies the first `fraction` of the file's bytes to `target`.
void truncate_copy(const std::string& file, const std::string& target, double fraction);

}  // namespace isosid::test
