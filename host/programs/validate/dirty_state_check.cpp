#include "dirty_state_check.hpp"

#include <cstring>

#include "dirty_gl_state.hpp"
#include "render_rig.hpp"
#include "synthetic_inputs.hpp"

namespace pfx::validate {
namespace {

using pfx::app::DirtyGlItem;
using pfx::app::DirtyGlState;

bool same_bits(const pfx::app::Image& a, const pfx::app::Image& b) {
  return a.rgba.size() == b.rgba.size() && std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

// create, one frame and destroy with `dirty()` in force around each (the inputs are uploaded and
// the output read back in a clean state). Problems with the engine's state reading back are
// reported; the frame is returned in *output (empty when it failed).
void run_dirty(RenderRig& rig, const std::string& effect_id, const pfx::app::Image& input,
               const std::vector<const DirtyGlItem*>& items, const std::string& label, pfx::app::Image* output,
               CheckReporter& report) {
  auto dirty = [&] {
    for (const DirtyGlItem* item : items) item->make_dirty();
  };
  auto clean = [&] {
    for (const DirtyGlItem* item : items) item->make_clean();
  };
  auto read = [&] {
    std::vector<std::vector<double>> values;
    for (const DirtyGlItem* item : items) values.push_back(item->read());
    return values;
  };
  auto compare = [&](const std::vector<std::vector<double>>& before, const std::string& what) {
    const std::vector<std::vector<double>> after = read();
    for (size_t i = 0; i < items.size(); ++i)
      if (after[i] != before[i]) report.problem(what + " changed the engine's GL state: " + items[i]->name);
  };
  output->rgba.clear();
  dirty();
  std::vector<std::vector<double>> engine = read();
  const bool created = rig.add_effect(effect_id);
  compare(engine, label + ": create");
  clean();
  if (!created) return;
  rig.set_around_chain(
      [&] {
        dirty();
        engine = read();
      },
      [&] {
        compare(engine, label + ": render");
        clean();
      });
  rig.render(input, label, output);
  rig.set_around_chain(nullptr, nullptr);
  dirty();
  engine = read();
  rig.remove_effect();
  compare(engine, label + ": destroy");
  clean();
}

}  // namespace

void check_dirty_state(const std::string& path, const std::string& effect_id, CheckReporter& report) {
  RenderRig rig(report);
  if (!rig.open(path) || !rig.add_effect(effect_id)) return;
  const pfx::app::Image input = gradient_image(48, 32);
  pfx::app::Image clean_output, dirty_output;
  if (!rig.render(input, "gradient 48x32 in a clean context", &clean_output)) return;
  rig.remove_effect();

  report.step("create, render and destroy under an engine's leftover GL state");
  const DirtyGlState state;
  std::vector<const DirtyGlItem*> all;
  for (const DirtyGlItem& item : state.items()) all.push_back(&item);
  run_dirty(rig, effect_id, input, all, "under every item of leftover state", &dirty_output, report);
  if (dirty_output.rgba.empty() || same_bits(clean_output, dirty_output)) return;

  // Name the items that change the picture, one at a time.
  std::string culprits;
  for (const DirtyGlItem* item : all) {
    pfx::app::Image output;
    run_dirty(rig, effect_id, input, {item}, "under " + item->name, &output, report);
    if (!output.rgba.empty() && !same_bits(clean_output, output)) culprits += (culprits.empty() ? "" : "; ") + item->name;
  }
  report.problem("the output under an engine's leftover GL state differs from a clean context's (gradient 48x32); "
                 "alone, these change it: " + (culprits.empty() ? std::string("none (only together)") : culprits));
}

}  // namespace pfx::validate
