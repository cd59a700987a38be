// libstdc++'s std::lerp for t in [0, 1], as the reference calls it.
double lerp(double a, double b, double t) {
  if ((a <= 0.0lf && b >= 0.0lf) || (a >= 0.0lf && b <= 0.0lf)) return t * b + (1.0lf - t) * a;
  if (t == 1.0lf) return b;
  double x = a + t * (b - a);
  return (t > 1.0lf) == (b > a) ? max(b, x) : min(b, x);
}
