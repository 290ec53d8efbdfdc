#include "statics/dof_constraints.hpp"

namespace bpm {

void apply_constraints(SparseMatrixRM& K, Eigen::VectorXd& f, const DofConstraints& c,
                       std::size_t first_row) {
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  double* value = K.valuePtr();
  const auto rows = static_cast<std::ptrdiff_t>(K.rows());
  // Row by row (so a rank's rows alone suffice): the fixed columns of a free row move to its
  // right-hand side, in ascending column order; a fixed row keeps only its diagonal.
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t local = 0; local < rows; ++local) {
    const std::size_t i = first_row + static_cast<std::size_t>(local);
    if (!c.fixed[i]) {
      for (int e = outer[local]; e < outer[local + 1]; ++e) {
        const auto j = static_cast<std::size_t>(inner[e]);
        if (j == i || !c.fixed[j]) continue;
        f[local] -= value[e] * c.value[j];
        value[e] = 0.0;
      }
      continue;
    }
    double diagonal = 1.0;
    for (int e = outer[local]; e < outer[local + 1]; ++e) {
      if (static_cast<std::size_t>(inner[e]) == i) diagonal = value[e] > 0.0 ? value[e] : 1.0;
    }
    for (int e = outer[local]; e < outer[local + 1]; ++e)
      value[e] = static_cast<std::size_t>(inner[e]) == i ? diagonal : 0.0;
    f[local] = diagonal * c.value[i];
  }
  // The eliminated entries and the assembly's exact zeros take no part in products or smoothers.
  K.prune([](Eigen::Index, Eigen::Index, double v) { return v != 0.0; });
}

}  // namespace bpm
