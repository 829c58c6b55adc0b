// The algebra itself (ALG-1 .. ALG-6): axioms on random multivectors, in Cl(3,0), PGA
// Cl(3,0,1) and, to show the code is generic, Cl(1,3).
//
// Random coefficients lie on a 2^-20 grid and are at most 4 in size, so every product of
// three multivectors needs far fewer than 256 bits: the arithmetic is exact and the axioms
// are checked for exact equality, not within a tolerance.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/reference/cl3.hpp>
#include <rotorcert/reference/series.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace {

using namespace rotorcert::ref;
using rotorcert::testing::multivector;
/// Where arithmetic rounds (transcendentals, elimination), the spec's "ref" class bounds it.
const Real& bar() { return rotorcert::testing::ref_class_bar(); }
using Cl13 = Algebra<1, 3, 0>;
template <class A> using MV = Multivector<A, Real>;

template <class A>
bool equal(const MV<A>& a, const MV<A>& b) { return a.c == b.c; }

template <class A>
MV<A> named(const char* name) { return blade_from_name<A, Real>(name); }

TEST(Algebra, BasisVectorsSquareToTheMetric) {
  RC_CLAUSE("ALG-1");
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(equal(gp(MV<Cl3>::vector(k), MV<Cl3>::vector(k)), MV<Cl3>(Real(1))));
  EXPECT_TRUE(equal(gp(named<PGA3>("e0"), named<PGA3>("e0")), MV<PGA3>()));  // e0^2 = 0
  for (const char* e : {"e1", "e2", "e3"}) EXPECT_TRUE(equal(gp(named<PGA3>(e), named<PGA3>(e)), MV<PGA3>(Real(1))));
  EXPECT_TRUE(equal(gp(named<Cl13>("e1"), named<Cl13>("e1")), MV<Cl13>(Real(1))));
  EXPECT_TRUE(equal(gp(named<Cl13>("e2"), named<Cl13>("e2")), MV<Cl13>(Real(-1))));
}

TEST(Algebra, BladeBitmapsAndNames) {
  RC_CLAUSE("ALG-1");
  EXPECT_EQ(Cl3::blade_name(1), "e1");
  EXPECT_EQ(Cl3::blade_name(6), "e23");
  EXPECT_EQ(Cl3::blade_name(5), "e13");
  EXPECT_EQ(PGA3::blade_name(1), "e0");
  EXPECT_EQ(PGA3::blade_name(15), "e0123");
  // e31 is the spec's name of -e13; e032 = -e023; e021 = -e012; e013 keeps its sign.
  EXPECT_TRUE(equal(named<Cl3>("e31"), -MV<Cl3>::blade(5)));
  EXPECT_TRUE(equal(named<PGA3>("e032"), -MV<PGA3>::blade(13)));
  EXPECT_TRUE(equal(named<PGA3>("e021"), -MV<PGA3>::blade(7)));
  EXPECT_TRUE(equal(named<PGA3>("e013"), MV<PGA3>::blade(11)));
  EXPECT_THROW(named<Cl3>("e4"), std::invalid_argument);
  EXPECT_THROW(named<Cl3>("x12"), std::invalid_argument);
}

TEST(Algebra, DistinctBasisVectorsAnticommute) {
  RC_CLAUSE("ALG-2");
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) {
        const MV<Cl3> a = MV<Cl3>::vector(i), b = MV<Cl3>::vector(j);
        EXPECT_TRUE(equal(gp(a, b), -gp(b, a))) << i << " " << j;
      }
}

template <class A>
void check_product_axioms() {
  const auto x = *multivector<A>(), y = *multivector<A>(), z = *multivector<A>();
  RC_ASSERT(equal(gp(gp(x, y), z), gp(x, gp(y, z))));                    // associative
  RC_ASSERT(equal(gp(x, y + z), gp(x, y) + gp(x, z)));                    // left distributive
  RC_ASSERT(equal(gp(x + y, z), gp(x, z) + gp(y, z)));                    // right distributive
  RC_ASSERT(equal(op(op(x, y), z), op(x, op(y, z))));                     // outer product associative
  RC_ASSERT(equal(reverse(gp(x, y)), gp(reverse(y), reverse(x))));        // ALG-4: reverse anti-automorphism
  RC_ASSERT(equal(involute(gp(x, y)), gp(involute(x), involute(y))));     // ALG-4: involution automorphism
  RC_ASSERT(equal(conjugate(x), reverse(involute(x))));
  MV<A> sum;
  for (int k = 0; k <= A::dimension; ++k) sum = sum + grade(x, k);
  RC_ASSERT(equal(sum, x));                                               // grades partition
}

RC_GTEST_PROP(Algebra, ProductAxiomsCl3, ()) {
  RC_CLAUSE("ALG-2");
  RC_CLAUSE("ALG-4");
  check_product_axioms<Cl3>();
}
RC_GTEST_PROP(Algebra, ProductAxiomsPGA, ()) {
  RC_CLAUSE("ALG-2");
  RC_CLAUSE("ALG-7");
  check_product_axioms<PGA3>();
}
RC_GTEST_PROP(Algebra, ProductAxiomsCl13, ()) {
  RC_CLAUSE("ALG-2");
  check_product_axioms<Cl13>();
}

/// ALG-3: for basis blades, the outer product and left contraction are the grade (a + b)
/// and grade (b - a) parts of the geometric product.
template <class A>
void check_products_are_grade_selections() {
  for (Bitmap a = 0; a < Bitmap(A::size); ++a)
    for (Bitmap b = 0; b < Bitmap(A::size); ++b) {
      const MV<A> x = MV<A>::blade(a), y = MV<A>::blade(b), g = gp(x, y);
      const int ga = grade_of(a), gb = grade_of(b);
      EXPECT_TRUE(equal(op(x, y), grade(g, ga + gb))) << a << " ^ " << b;
      EXPECT_TRUE(equal(lc(x, y), gb >= ga ? grade(g, gb - ga) : MV<A>())) << a << " _| " << b;
      EXPECT_EQ(scp(x, y), g.c[0]);
    }
}

TEST(Algebra, OuterAndContractionAreGradeSelections) {
  RC_CLAUSE("ALG-3");
  check_products_are_grade_selections<Cl3>();
  check_products_are_grade_selections<PGA3>();
  check_products_are_grade_selections<Cl13>();
}

RC_GTEST_PROP(Algebra, VectorProductSplitsIntoContractionAndWedge, ()) {
  RC_CLAUSE("ALG-3");
  const auto a = grade(*multivector<Cl3>(), 1), b = grade(*multivector<Cl3>(), 1);
  RC_ASSERT(equal(gp(a, b), lc(a, b) + op(a, b)));  // ab = a.b + a^b
  RC_ASSERT(equal(lc(a, b), lc(b, a)));
  RC_ASSERT(equal(op(a, b), -op(b, a)));
}

TEST(Algebra, ReverseSignsByGrade) {
  RC_CLAUSE("ALG-4");
  const int expected[4] = {+1, +1, -1, -1};
  for (Bitmap b = 0; b < 8; ++b)
    EXPECT_TRUE(equal(reverse(MV<Cl3>::blade(b)), Real(expected[grade_of(b)]) * MV<Cl3>::blade(b))) << b;
}

TEST(Algebra, PseudoscalarSquaresToMinusOneAndDualsVectorsToPlanes) {
  RC_CLAUSE("ALG-5");
  const MV<Cl3> I = cl3::I<Real>();
  EXPECT_TRUE(equal(gp(I, I), MV<Cl3>(Real(-1))));
  // e1 I = e23, e2 I = e31, e3 I = e12: the bivector dual to each axis, cyclic.
  EXPECT_TRUE(equal(gp(named<Cl3>("e1"), I), named<Cl3>("e23")));
  EXPECT_TRUE(equal(gp(named<Cl3>("e2"), I), named<Cl3>("e31")));
  EXPECT_TRUE(equal(gp(named<Cl3>("e3"), I), named<Cl3>("e12")));
  // Dorst et al.'s dual A* = A _| I^-1 gives e1* = -e23 (the paper's I A would give +e23).
  EXPECT_TRUE(equal(cl3::dual(named<Cl3>("e1")), -named<Cl3>("e23")));
}

RC_GTEST_PROP(Algebra, PseudoscalarIsCentralAndDualInverts, ()) {
  RC_CLAUSE("ALG-5");
  const auto x = *multivector<Cl3>();
  const MV<Cl3> I = cl3::I<Real>();
  RC_ASSERT(equal(gp(I, x), gp(x, I)));
  RC_ASSERT(equal(cl3::undual(cl3::dual(x)), x));
}

RC_GTEST_PROP(Algebra, GenericInverseMatchesVersorInverse, ()) {
  RC_CLAUSE("ALG-6");
  const auto x = even(*multivector<Cl3>());
  const Real n = gp(x, reverse(x)).c[0];
  RC_PRE(n != 0);
  const auto inv = inverse(x);
  RC_ASSERT(inv.has_value());
  const auto versor_inverse = reverse(x) / n;
  RC_ASSERT(norm1(*inv - versor_inverse) <= bar());  // Gaussian elimination rounds
}

TEST(Algebra, RotorRotatesRightHandedAboutItsAxis) {
  RC_CLAUSE("ALG-6");
  // R = exp(-I e3 theta/2) = cos(theta/2) - e12 sin(theta/2) must take e1 to cos(theta) e1 + sin(theta) e2.
  const Real theta = Real(1) / Real(3);
  const Real h = theta / Real(2);
  const MV<Cl3> R = MV<Cl3>(cos(h)) - sin(h) * named<Cl3>("e12");
  const MV<Cl3> rotated = gp(gp(R, named<Cl3>("e1")), reverse(R));
  const MV<Cl3> expected = cos(theta) * named<Cl3>("e1") + sin(theta) * named<Cl3>("e2");
  EXPECT_LE(norm1(rotated - expected), bar());
  // The same rotor written as exp of the bivector -I e3 theta/2, through the generic series.
  const MV<Cl3> B = Real(-1) * h * gp(cl3::I<Real>(), named<Cl3>("e3"));
  EXPECT_LE(norm1(exp_series(B) - R), bar());
}

RC_GTEST_PROP(Algebra, RotorsPreserveGradeAndComposeByProduct, ()) {
  RC_CLAUSE("ALG-6");
  const auto a = even(*multivector<Cl3>()), b = even(*multivector<Cl3>());
  RC_PRE(gp(a, reverse(a)).c[0] > Real(1) / Real(64) && gp(b, reverse(b)).c[0] > Real(1) / Real(64));
  const auto x = grade(*multivector<Cl3>(), 1);
  const auto once = cl3::sandwich(b, cl3::sandwich(a, x));
  const auto composed = cl3::sandwich(gp(b, a), x);  // apply a first, then b
  RC_ASSERT(norm1(once - composed) <= bar());
  RC_ASSERT(norm1(grade(composed, 1) - composed) == 0);  // still a vector
  RC_ASSERT(abs(scp(composed, composed) - scp(x, x)) <= bar());  // same length
}

}  // namespace
