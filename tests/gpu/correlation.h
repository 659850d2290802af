#pragma once
// Pearson's correlation of two equally long series: how the GPU tests compare the GPU's images and
// volumes with the CPU's at equal sample counts (sampling noise aside, they should agree).
#include <cmath>
#include <cstddef>
#include <vector>

namespace gridifs::test {

template <typename T>
double correlation(const std::vector<T>& a, const std::vector<T>& b) {
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += double(a[i]), mb += double(b[i]);
  ma /= double(a.size());
  mb /= double(b.size());
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (double(a[i]) - ma) * (double(b[i]) - mb);
    saa += (double(a[i]) - ma) * (double(a[i]) - ma);
    sbb += (double(b[i]) - mb) * (double(b[i]) - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

}  // namespace gridifs::test
