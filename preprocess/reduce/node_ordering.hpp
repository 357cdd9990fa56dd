// A fill-reducing ordering computed on a stiffness's node graph. The DOFs of one control point
// (its two or three displacements) couple to the same DOFs, so their columns share one pattern:
// ordering the graph of such groups (supervariables) instead of the DOF graph gives the same
// fill with a graph of about a ninth of the entries. CHOLMOD's own analysis orders the DOF graph;
// at 1e6 DOFs its METIS ran for minutes at over 20 GB before it could say that the factor
// would not fit, and here it is seconds and a few GB.
#pragma once
#include <Eigen/Sparse>
#include <cholmod.h>
#include <vector>

namespace isosid::prep {

/// The permutation of A's columns (new position -> column) that CHOLMOD's ordering of A's
/// supervariable graph gives: the groups of columns with equal patterns in the order of their
/// graph's fill-reducing ordering (AMD, or METIS where it fills less, as CHOLMOD chooses), each
/// group's columns in ascending order. A is symmetric; its lower triangle is read.
/// `common` is the CHOLMOD workspace of the factorization it is for.
std::vector<int> node_graph_ordering(const Eigen::SparseMatrix<double>& A, cholmod_common& common);

/// Count of the supervariables (groups of columns with equal patterns) of symmetric A's lower triangle.
Eigen::Index supervariable_count(const Eigen::SparseMatrix<double>& A);

}  // namespace isosid::prep
