// gram (src/loop/gram.hpp): J^T J with the zero products skipped equals
// Eigen's `J.transpose() * J` bit for bit.  Expected answer: every entry the
// same bits (memcmp) on Jacobian-like matrices of every shape the order of
// sums depends on: p = 2..70 columns (4-row and 2-row panels, a last single
// row, remaining columns), n from 32 to 60,000 rows (depth blocks, the peeled
// 8 rows and the rest, even and odd rows), dense, a group factor (dense base
// columns plus one level column per row, as a fit with a 42-level coil),
// random zeros, values of mixed sign and magnitude (so that the order of the
// sums shows in the last bits), and rows with no nonzero entry.  In the
// sanitizer step (tests/common/sanitizer_run.hpp) every third p of each n
// (steps of 3 and 21 from p = 2 still take every residue of p modulo 4).
#define BOOST_TEST_MODULE gram
#include <boost/test/unit_test.hpp>
#include <cstring>
#include <random>

#include "loop/gram.hpp"
#include "sanitizer_run.hpp"

using namespace drawbend::loop;

namespace {

Eigen::MatrixXd jacobian(int n, int p, int kind, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-20, 20);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, p);
  const int base = std::min(p, 1 + static_cast<int>(rng() % 9));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < p; ++j) {
      bool nz = true;
      if (kind == 1) nz = j < base || j == base + k % std::max(1, p - base);
      if (kind == 2) nz = rng() % 5 == 0;
      if (kind == 3) nz = k % 7 != 3 && (j < base || rng() % 11 == 0);
      if (nz) J(k, j) = std::ldexp(u(rng), e(rng));
    }
  return J;
}

}  // namespace

BOOST_AUTO_TEST_CASE(same_bits_as_eigen) {
  std::mt19937_64 rng(20261203);
  const int ns[] = {32, 33, 39, 40, 41, 100, 257, 1000, 4099, 12345, 60001};
  int checked = 0, differing = 0;
  for (int n : ns)
    for (int p = 2; p <= 70; p += (n > 5000 ? 7 : 1) * (drawbend::test::sanitizer_run() ? 3 : 1))
      for (int kind = 0; kind < 4; ++kind) {
        const Eigen::MatrixXd J = jacobian(n, p, kind, rng);
        const Eigen::MatrixXd ref = J.transpose() * J;
        Eigen::MatrixXd A;
        BOOST_REQUIRE(gram_sparse(J, A, true));
        ++checked;
        if (std::memcmp(A.data(), ref.data(), sizeof(double) * p * p) != 0) {
          ++differing;
          BOOST_TEST_MESSAGE("n " << n << " p " << p << " kind " << kind << ": bits differ");
        }
        const Eigen::MatrixXd G = gram(J);
        BOOST_CHECK(std::memcmp(G.data(), ref.data(), sizeof(double) * p * p) == 0);
        // with the rows of each column given (a superset: every third zero row too)
        std::vector<std::vector<int>> nz(p);
        for (int j = 0; j < p; ++j)
          for (int k = 0; k < n; ++k)
            if (J(k, j) != 0 || k % 3 == 0) nz[j].push_back(k);
        Eigen::MatrixXd B;
        BOOST_REQUIRE(gram_sparse(J, B, true, &nz));
        BOOST_CHECK(std::memcmp(B.data(), ref.data(), sizeof(double) * p * p) == 0);
      }
  BOOST_TEST_MESSAGE(checked << " matrices compared");
  BOOST_CHECK_EQUAL(differing, 0);
}

BOOST_AUTO_TEST_CASE(not_finite_falls_back) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(100, 5), A;
  J(3, 2) = std::numeric_limits<double>::quiet_NaN();
  BOOST_CHECK(!gram_sparse(J, A, true));
  std::vector<std::vector<int>> nz(5);
  nz[2] = {3};
  BOOST_CHECK(!gram_sparse(J, A, true, &nz));
}
