// Composition and enhancement (SPEC 2.11; Lee §6, Eq. 6).
//   D_i' = D_i (1 - a D_c)          interior strokes fade where contours are
//   I    = (1 - D_c)(1 - D_i')
//   I''  = mix(I, smoothstep(0, 1, I), contrast)    (Majumder & Gopi)
//   out  = I'' c_p                  c_p the paper color (white without paper)
#pragma once

namespace plumbago {

struct ComposeParams {
  static constexpr const char* stage = "compose";
  float contour_attenuation, contrast;
  template <class V>
  void visit(V& v) {
    v.real(contour_attenuation, "contour_attenuation", 0.5, 0.0, 1.0,
           "a: how much contours fade the interior strokes under them (SPEC 2.11)");
    v.real(contrast, "contrast", 0.5, 0.0, 1.0, "weight of the smoothstep contrast enhancement (Lee §6)");
  }
};

}  // namespace plumbago
