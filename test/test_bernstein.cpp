// Tests of fair::Bernstein_polynomial: exact identities in Gmpq (and EPECK's FT), and agreement
// of every supported number type with the exact result (enclosure for intervals, closeness for
// floating types), on seeded random polynomials.

#include <fair/Bernstein_polynomial.h>
#include <fair/internal/common/exact_conversion.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

typedef CGAL::Gmpq Q;
typedef fair::Bernstein_polynomial<Q> PQ;
typedef CGAL::Interval_nt<> I;
typedef CGAL::Epeck::FT Lazy;

// Random dyadic values k / 64, exactly representable in every number type under test.
std::vector<double> random_dyadics(std::mt19937& rng, std::size_t count) {
  std::uniform_int_distribution<int> d(-4000, 4000);
  std::vector<double> v(count);
  for (double& x : v) x = d(rng) / 64.0;
  return v;
}

std::vector<Q> to_q(const std::vector<double>& v) { return std::vector<Q>(v.begin(), v.end()); }

Q horner(const std::vector<Q>& a, const Q& x) {
  Q v(0);
  for (std::size_t k = a.size(); k-- > 0;) v = v * x + a[k];
  return v;
}

std::vector<Q> sample_points() {
  return {Q(0), Q(1), Q(1, 2), Q(1, 3), Q(2, 7), Q(99, 100), Q(-3, 2), Q(5, 2), Q(1, 1000003)};
}

// ------------------------------------------------------------------ exact identities in Gmpq

TEST(BernsteinExact, DeCasteljauEqualsPowerBasisHorner) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 60; ++trial) {
    const PQ p(to_q(random_dyadics(rng, 1 + trial % 12)));
    const std::vector<Q> a = p.to_power_basis();
    for (const Q& t : sample_points()) EXPECT_EQ(p(t), horner(a, t)) << p << " at " << t;
  }
}

TEST(BernsteinExact, PowerBasisRoundTrip) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<Q> b = to_q(random_dyadics(rng, 1 + trial % 15));
    EXPECT_EQ(PQ::from_power_basis(PQ(b).to_power_basis()).coefficients(), b);
    EXPECT_EQ(PQ::from_power_basis(b).to_power_basis(), b);
  }
}

TEST(BernsteinExact, KnownBasisConversions) {
  // t in degree 1 is (0, 1); t^2 in degree 2 is (0, 0, 1); 1 - t is (1, 0).
  EXPECT_EQ(PQ::from_power_basis({Q(0), Q(1)}).coefficients(), (std::vector<Q>{Q(0), Q(1)}));
  EXPECT_EQ(PQ::from_power_basis({Q(0), Q(0), Q(1)}).coefficients(), (std::vector<Q>{Q(0), Q(0), Q(1)}));
  EXPECT_EQ(PQ::from_power_basis({Q(1), Q(-1)}).coefficients(), (std::vector<Q>{Q(1), Q(0)}));
  // t written in degree 3: the coefficients are i/3 (linear precision).
  EXPECT_EQ(PQ({Q(0), Q(1)}).elevated(2).coefficients(), (std::vector<Q>{Q(0), Q(1, 3), Q(2, 3), Q(1)}));
  // 1 = sum of the Bernstein basis (partition of unity): all coefficients 1, power form 1.
  EXPECT_EQ(PQ(std::vector<Q>(5, Q(1))).to_power_basis(), (std::vector<Q>{Q(1), Q(0), Q(0), Q(0), Q(0)}));
}

TEST(BernsteinExact, SplitPiecesAreReparametrisations) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 30; ++trial) {
    const PQ p(to_q(random_dyadics(rng, 1 + trial % 9)));
    for (const Q& t : {Q(1, 2), Q(1, 3), Q(7, 8), Q(0), Q(1), Q(3, 2)}) {
      const std::pair<PQ, PQ> s = p.split(t);
      ASSERT_EQ(s.first.degree(), p.degree());
      ASSERT_EQ(s.second.degree(), p.degree());
      for (const Q& u : sample_points()) {
        EXPECT_EQ(s.first(u), p(t * u));
        EXPECT_EQ(s.second(u), p(t + (1 - t) * u));
      }
      // The pieces join: the last left coefficient is the first right one, p(t).
      EXPECT_EQ(s.first[p.degree()], p(t));
      EXPECT_EQ(s.second[0], p(t));
    }
  }
}

TEST(BernsteinExact, RestrictionIsReparametrisation) {
  std::mt19937 rng(4);
  for (int trial = 0; trial < 30; ++trial) {
    const PQ p(to_q(random_dyadics(rng, 1 + trial % 9)));
    EXPECT_EQ(p.restricted(Q(0), Q(1)).coefficients(), p.coefficients());
    EXPECT_EQ(p.restricted(Q(1), Q(0)).coefficients(), p.reversed().coefficients());
    for (const std::pair<Q, Q>& ab : {std::make_pair(Q(1, 4), Q(3, 4)), std::make_pair(Q(1, 3), Q(1, 2)),
                                      std::make_pair(Q(2, 3), Q(1, 5)), std::make_pair(Q(-1), Q(2))}) {
      const PQ r = p.restricted(ab.first, ab.second);
      for (const Q& u : sample_points()) EXPECT_EQ(r(u), p(ab.first + (ab.second - ab.first) * u));
      // Restricting to [0,b] is the left piece of the split at b.
      EXPECT_EQ(p.restricted(Q(0), ab.second).coefficients(), p.split(ab.second).first.coefficients());
    }
  }
}

TEST(BernsteinExact, DerivativeMatchesPowerBasis) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 30; ++trial) {
    const PQ p(to_q(random_dyadics(rng, 2 + trial % 10)));
    const std::vector<Q> a = p.to_power_basis();
    std::vector<Q> da;
    for (std::size_t k = 1; k < a.size(); ++k) da.push_back(Q(static_cast<long>(k)) * a[k]);
    EXPECT_EQ(p.derivative().to_power_basis(), da);
    EXPECT_EQ(p.derivative().degree(), p.degree() - 1);
  }
  const PQ c({Q(7)});
  EXPECT_TRUE(c.derivative().is_zero());
  EXPECT_EQ(c.derivative().degree(), 0u);
}

TEST(BernsteinExact, ElevationKeepsThePolynomial) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 30; ++trial) {
    const PQ p(to_q(random_dyadics(rng, 1 + trial % 8)));
    const PQ e = p.elevated(3);
    EXPECT_EQ(e.degree(), p.degree() + 3);
    EXPECT_EQ(e[0], p[0]);
    EXPECT_EQ(e[e.degree()], p[p.degree()]);
    EXPECT_EQ(p.elevated(0).coefficients(), p.coefficients());
    for (const Q& u : sample_points()) EXPECT_EQ(e(u), p(u));
  }
}

TEST(BernsteinExact, ArithmeticIdentities) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 30; ++trial) {
    const PQ p(to_q(random_dyadics(rng, 1 + trial % 7)));
    const PQ q(to_q(random_dyadics(rng, 1 + (trial * 5) % 6)));
    const PQ sum = p + q, diff = p - q, prod = p * q, neg = -p, scaled = Q(3, 7) * p;
    EXPECT_EQ(sum.degree(), std::max(p.degree(), q.degree()));
    EXPECT_EQ(prod.degree(), p.degree() + q.degree());
    for (const Q& u : sample_points()) {
      EXPECT_EQ(sum(u), p(u) + q(u));
      EXPECT_EQ(diff(u), p(u) - q(u));
      EXPECT_EQ(prod(u), p(u) * q(u));
      EXPECT_EQ(neg(u), -p(u));
      EXPECT_EQ(scaled(u), Q(3, 7) * p(u));
      EXPECT_EQ((p * Q(2))(u), 2 * p(u));
    }
    EXPECT_TRUE((p - p).is_zero());
    PQ acc = p;
    acc += q;
    acc -= q;
    acc *= q;
    for (const Q& u : sample_points()) EXPECT_EQ(acc(u), p(u) * q(u));
  }
}

TEST(BernsteinExact, SignVariations) {
  EXPECT_EQ(fair::sign_variations(PQ({Q(3), Q(-1), Q(2), Q(-5)})), 3);
  EXPECT_EQ(fair::sign_variations(PQ({Q(1), Q(0), Q(0), Q(-1)})), 1);
  EXPECT_EQ(fair::sign_variations(PQ({Q(1), Q(0), Q(-1), Q(0), Q(1)})), 2);
  EXPECT_EQ(fair::sign_variations(PQ({Q(0), Q(0), Q(0)})), 0);
  EXPECT_EQ(fair::sign_variations(PQ({Q(-2), Q(-1), Q(-5)})), 0);
  EXPECT_EQ(fair::sign_variations(PQ()), 0);
  // Descartes bound holds on random products of linear factors with known roots in (0,1):
  // variations >= number of roots and of the same parity.
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> d(1, 99);
  for (int trial = 0; trial < 40; ++trial) {
    PQ p({Q(1)});
    int inside = 0;
    for (int k = 0; k < 1 + trial % 6; ++k) {
      const Q r(d(rng) * (k % 2 ? 1 : 3) - 50, 100); // some roots outside [0,1]
      if (r > 0 && r < 1) ++inside;
      p *= PQ({-r, 1 - r});
    }
    const int v = fair::sign_variations(p);
    EXPECT_GE(v, inside);
    EXPECT_EQ((v - inside) % 2, 0);
  }
}

TEST(BernsteinExact, IntervalSignVariationBounds) {
  const fair::Sign_variation_count a = fair::sign_variation_bounds(
      fair::Bernstein_polynomial<I>({I(-1, 1), I(2)}));
  EXPECT_EQ(a.lower, 0);
  EXPECT_EQ(a.upper, 1);
  EXPECT_FALSE(a.certain());
  const fair::Sign_variation_count b = fair::sign_variation_bounds(
      fair::Bernstein_polynomial<I>({I(1, 2), I(-1, 1), I(1, 2)}));
  EXPECT_EQ(b.lower, 0);
  EXPECT_EQ(b.upper, 2);
  const fair::Sign_variation_count c = fair::sign_variation_bounds(
      fair::Bernstein_polynomial<I>({I(1, 2), I(0, 1), I(-3, -2)}));
  EXPECT_TRUE(c.certain()); // [0,1] can only be 0 or +: exactly one variation
  EXPECT_EQ(c.count(), 1);
  const fair::Sign_variation_count z = fair::sign_variation_bounds(fair::Bernstein_polynomial<I>({I(-1, 1)}));
  EXPECT_TRUE(z.certain());
  EXPECT_EQ(z.count(), 0);
  EXPECT_THROW(fair::sign_variations(fair::Bernstein_polynomial<I>({I(1, 2), I(-1, 1), I(1, 2)})),
               fair::Precondition_error);
  EXPECT_THROW(b.count(), fair::Precondition_error);
  EXPECT_EQ(fair::sign_variations(fair::Bernstein_polynomial<I>({I(3), I(-1), I(2), I(-5)})), 3);
}

TEST(BernsteinExact, PreconditionsAndZero) {
  EXPECT_THROW(PQ(std::vector<Q>{}), fair::Precondition_error);
  EXPECT_THROW(PQ::from_power_basis({}), fair::Precondition_error);
  const PQ zero;
  EXPECT_EQ(zero.degree(), 0u);
  EXPECT_TRUE(zero.is_zero());
  EXPECT_FALSE(PQ({Q(0), Q(1, 1000000)}).is_zero());
  EXPECT_TRUE(fair::Bernstein_polynomial<I>({I(0), I(0)}).is_zero());
  EXPECT_FALSE(fair::Bernstein_polynomial<I>({I(0), I(-1, 1)}).is_zero()); // possibly nonzero
  try {
    PQ(std::vector<Q>{});
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos);
  }
}

// ------------------------------------------------------------------ every NT agrees with Gmpq

template <class NT>
struct Check;
template <>
struct Check<Q> {
  static void close(const Q& x, const Q& ref, double) { EXPECT_EQ(x, ref); }
};
template <>
struct Check<Lazy> {
  static void close(const Lazy& x, const Q& ref, double) {
    EXPECT_EQ(fair::internal::common::to_gmpq(x), ref);
  }
};
template <>
struct Check<I> { // the interval result must enclose the exact value
  static void close(const I& x, const Q& ref, double) {
    EXPECT_LE(Q(x.inf()), ref);
    EXPECT_GE(Q(x.sup()), ref);
    EXPECT_LE(x.sup() - x.inf(), 1e-9 * (1 + std::fabs(CGAL::to_double(ref))));
  }
};
template <>
struct Check<double> {
  static void close(double x, const Q& ref, double scale) {
    EXPECT_NEAR(x, CGAL::to_double(ref), 1e-12 * scale);
  }
};
template <>
struct Check<CGAL::Gmpfr> {
  static void close(const CGAL::Gmpfr& x, const Q& ref, double scale) {
    EXPECT_NEAR(CGAL::to_double(x), CGAL::to_double(ref), 1e-12 * scale);
  }
};

template <class NT>
class BernsteinTyped : public ::testing::Test {
protected:
  typedef fair::Bernstein_polynomial<NT> P;
  static P make(const std::vector<double>& v) { return P(std::vector<NT>(v.begin(), v.end())); }
  static void same(const P& p, const PQ& ref, double scale) {
    ASSERT_EQ(p.degree(), ref.degree());
    for (std::size_t i = 0; i <= p.degree(); ++i) Check<NT>::close(p[i], ref[i], scale);
  }
};

typedef ::testing::Types<double, I, Q, Lazy, CGAL::Gmpfr> Number_types;
TYPED_TEST_SUITE(BernsteinTyped, Number_types);

TYPED_TEST(BernsteinTyped, OperationsAgreeWithExactArithmetic) {
  typedef TypeParam NT;
  std::mt19937 rng(9);
  const NT half(0.5), quarter(0.25), three_quarters(0.75), t(0.375);
  for (int trial = 0; trial < 12; ++trial) {
    const std::vector<double> bv = random_dyadics(rng, 1 + trial % 7), cv = random_dyadics(rng, 1 + trial % 4);
    const auto p = TestFixture::make(bv), q = TestFixture::make(cv);
    const PQ pq(to_q(bv)), qq(to_q(cv));
    const double scale = 4000.0 * 4000.0;
    Check<NT>::close(p(t), pq(Q(0.375)), scale);
    Check<NT>::close(p.evaluate(half), pq(Q(1, 2)), scale);
    TestFixture::same(p.split(half).first, pq.split(Q(1, 2)).first, scale);
    TestFixture::same(p.split(t).second, pq.split(Q(0.375)).second, scale);
    TestFixture::same(p.restricted(quarter, three_quarters), pq.restricted(Q(1, 4), Q(3, 4)), scale);
    TestFixture::same(p.derivative(), pq.derivative(), scale);
    TestFixture::same(p.elevated(2), pq.elevated(2), scale);
    TestFixture::same(p + q, pq + qq, scale);
    TestFixture::same(p - q, pq - qq, scale);
    TestFixture::same(p * q, pq * qq, scale);
    TestFixture::same(NT(3) * p, Q(3) * pq, scale);
    TestFixture::same(-p, -pq, scale);
    const std::vector<NT> a = p.to_power_basis();
    const std::vector<Q> aq = pq.to_power_basis();
    ASSERT_EQ(a.size(), aq.size());
    for (std::size_t k = 0; k < a.size(); ++k) Check<NT>::close(a[k], aq[k], scale * 64);
    TestFixture::same(fair::Bernstein_polynomial<NT>::from_power_basis(a), pq, scale * 64);
    EXPECT_EQ(fair::sign_variations(p), fair::sign_variations(pq));
  }
}

// ------------------------------------------------------------------ the one exact conversion

TEST(ExactConversion, EveryAcceptedNumberTypeConvertsExactly) {
  using fair::internal::common::to_gmpq;
  EXPECT_EQ(to_gmpq(0.1), Q(0.1)); // the dyadic rational the double stores
  EXPECT_EQ(to_gmpq(-7), Q(-7));
  EXPECT_EQ(to_gmpq(Q(1, 3)), Q(1, 3));
  EXPECT_EQ(to_gmpq(Lazy(1) / 3), Q(1, 3));
  EXPECT_EQ(to_gmpq(CGAL::Gmpfr(0.75)), Q(3, 4));
  EXPECT_EQ(to_gmpq(I(0.125)), Q(1, 8));
  boost::multiprecision::mpq_rational third(1);
  third /= 3;
  EXPECT_EQ(to_gmpq(third), Q(1, 3));
  EXPECT_EQ(fair::internal::common::from_gmpq<boost::multiprecision::mpq_rational>(Q(1, 3)), third);
#ifdef CGAL_USE_GMPXX
  EXPECT_EQ(to_gmpq(mpq_class(2, 5)), Q(2, 5));
#endif
  EXPECT_THROW(to_gmpq(std::nan("")), fair::Precondition_error);
  EXPECT_THROW(to_gmpq(HUGE_VAL), fair::Precondition_error);
  EXPECT_THROW(to_gmpq(CGAL::Gmpfr(std::nan(""))), fair::Precondition_error);
  EXPECT_THROW(to_gmpq(I(0, 1)), fair::Precondition_error);
}

} // namespace
