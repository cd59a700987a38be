// Visibility of stroke samples, CPU reference (Kalnins et al. 2002, §4.6): the test of
// common/strokes/visibility.hpp on the ID image, sample by sample.
#include "common/strokes/visibility.hpp"

#include <optional>

#include <tbb/parallel_for.h>

#include "common/strokes/id_image.hpp"
#include "reference/core/stage.hpp"

namespace plumbago::reference {

PLUMBAGO_REFERENCE_STAGE(visibility, [](ReferenceFrame& f) {
  const auto p = f.params<StrokesParams>();
  ImageU32 keys = keys_from_channels(f.get(kIds));
  std::optional<ImageU32> crease_keys;
  if (p.crease_under_silhouettes) crease_keys = keys_from_channels(f.get(kCreaseIds));
  const ImageU32* under = crease_keys ? &*crease_keys : nullptr;
  auto test = [&](const std::vector<VisibilitySample>& batch) {
    std::vector<uint8_t> flags(batch.size());
    tbb::parallel_for(size_t(0), batch.size(), [&](size_t k) { flags[k] = sample_visible(keys, under, batch[k]); });
    return flags;
  };
  Visibility v = visible_runs(f.get(kWindowLines), p, test);
  f.put(kFlags, flags_image(v.flags));
  auto [paths, ends] = run_tables(v.runs);
  f.put(kRunPaths, std::move(paths));
  f.put(kRunEnds, std::move(ends));
  f.put(kVisibleRuns, std::move(v));
});

}  // namespace plumbago::reference
