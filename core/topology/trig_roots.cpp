#include "core/topology/trig_roots.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tfd::core::topology {
namespace {

double poly(const double* c, int degree, double x) {
  double v = c[degree];
  for (int i = degree - 1; i >= 0; --i) v = v * x + c[i];
  return v;
}

/// Real roots of the monic-normalisable cubic d3 x³ + d2 x² + d1 x + d0 (d3 ≠ 0), ascending.
int cubicRealRoots(const double d[4], double out[3]) {
  const double p = d[2] / d[3], q = d[1] / d[3], r = d[0] / d[3];
  const double qq = (p * p - 3 * q) / 9, rr = (2 * p * p * p - 9 * p * q + 27 * r) / 54;
  int n = 0;
  if (rr * rr < qq * qq * qq) {
    const double t = std::acos(std::clamp(rr / std::sqrt(qq * qq * qq), -1.0, 1.0));
    const double s = -2 * std::sqrt(qq);
    out[0] = s * std::cos(t / 3) - p / 3;
    out[1] = s * std::cos((t + 2 * std::numbers::pi) / 3) - p / 3;
    out[2] = s * std::cos((t - 2 * std::numbers::pi) / 3) - p / 3;
    n = 3;
  } else {
    const double a =
        -std::copysign(std::cbrt(std::abs(rr) + std::sqrt(rr * rr - qq * qq * qq)), rr);
    const double b = a != 0 ? qq / a : 0;
    out[0] = a + b - p / 3;
    n = 1;
  }
  // Two Newton steps each against the cancellation of the closed form.
  for (int i = 0; i < n; ++i) {
    for (int it = 0; it < 2; ++it) {
      const double x = out[i];
      const double f = ((d[3] * x + d[2]) * x + d[1]) * x + d[0];
      const double fp = (3 * d[3] * x + 2 * d[2]) * x + d[1];
      if (fp != 0) out[i] = x - f / fp;
    }
  }
  std::sort(out, out + n);
  return n;
}

/// Root of the quartic in [lo, hi] where it is monotone with a sign change.
double bracketedRoot(const double c[5], double lo, double hi, double flo) {
  const double d[4] = {c[1], 2 * c[2], 3 * c[3], 4 * c[4]};
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const double f = poly(c, 4, x);
    if (f == 0) return x;
    if ((f > 0) == (flo > 0))
      lo = x, flo = f;
    else
      hi = x;
    const double fp = poly(d, 3, x);
    double next = fp != 0 ? x - f / fp : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 1e-16 * std::max(1.0, std::abs(x)) ||
        hi - lo <= 1e-16 * std::max(1.0, std::abs(x))) {
      return next;
    }
    x = next;
  }
  return x;
}

}  // namespace

int quarticRealRoots(const double c[5], double roots[4], bool nearDouble[4]) {
  double bound = 0;
  for (int i = 0; i < 4; ++i) bound = std::max(bound, std::abs(c[i] / c[4]));
  bound += 1;
  const double d[4] = {c[1], 2 * c[2], 3 * c[3], 4 * c[4]};
  double stationary[3];
  const int ns = cubicRealRoots(d, stationary);
  double knots[5];
  int nk = 0;
  knots[nk++] = -bound;
  for (int i = 0; i < ns; ++i)
    if (stationary[i] > -bound && stationary[i] < bound) knots[nk++] = stationary[i];
  knots[nk++] = bound;
  int n = 0;
  double fl = poly(c, 4, knots[0]);
  for (int k = 0; k + 1 < nk && n < 4; ++k) {
    const double l = knots[k], r = knots[k + 1];
    const double fr = poly(c, 4, r);
    if (fl == 0) {
      if (n == 0 || roots[n - 1] != l) roots[n] = l, nearDouble[n++] = false;
    } else if ((fl > 0) != (fr > 0) && fr != 0) {
      roots[n] = bracketedRoot(c, l, r, fl), nearDouble[n++] = false;
    } else if (k + 1 < nk - 1 && fr != 0) {
      // A stationary point where the quartic nearly touches zero without crossing it.
      const double x = r;
      double magnitude = 0, power = 1;
      for (int i = 0; i <= 4; ++i) magnitude += std::abs(c[i]) * power, power *= std::abs(x);
      if (std::abs(fr) <= 1e-10 * magnitude && n < 4) roots[n] = x, nearDouble[n++] = true;
    }
    fl = fr;
  }
  if (fl == 0 && n < 4 && (n == 0 || roots[n - 1] != knots[nk - 1]))
    roots[n] = knots[nk - 1], nearDouble[n++] = false;
  return n;
}

int trigQuadraticRoots(double a0, double a1, double b1, double a2, double b2,
                       std::array<TrigRoot, 4>& out) {
  const double scale = std::abs(a0) + std::abs(a1) + std::abs(b1) + std::abs(a2) + std::abs(b2);
  if (scale == 0) return 0;
  // Offset φ0 with |g(φ0 + π)| largest among 8 candidates: x = tan((θ − φ0)/2) stays finite.
  const auto g = [&](double t) {
    return a0 + a1 * std::cos(t) + b1 * std::sin(t) + a2 * std::cos(2 * t) + b2 * std::sin(2 * t);
  };
  double phi = 0, best = -1;
  for (int k = 0; k < 8; ++k) {
    const double candidate = k * std::numbers::pi / 8;
    const double v = std::abs(g(candidate + std::numbers::pi));
    if (v > best) best = v, phi = candidate;
  }
  if (best <= 1e-300) return 0;
  const double cp = std::cos(phi), sp = std::sin(phi), c2p = std::cos(2 * phi),
               s2p = std::sin(2 * phi);
  const double A0 = a0, A1 = a1 * cp + b1 * sp, B1 = -a1 * sp + b1 * cp;
  const double A2 = a2 * c2p + b2 * s2p, B2 = -a2 * s2p + b2 * c2p;
  const double c[5] = {A0 + A1 + A2, 2 * B1 + 4 * B2, 2 * A0 - 6 * A2, 2 * B1 - 4 * B2,
                       A0 - A1 + A2};
  double x[4];
  bool nearDouble[4];
  const int n = quarticRealRoots(c, x, nearDouble);
  for (int i = 0; i < n; ++i) out[i] = {phi + 2 * std::atan(x[i]), !nearDouble[i]};
  return n;
}

}  // namespace tfd::core::topology
