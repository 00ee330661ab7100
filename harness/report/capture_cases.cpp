#include "harness/report/capture_cases.hpp"

#include "harness/capture/capture.hpp"
#include "harness/core/error.hpp"
#include "harness/generators/generator_registry.hpp"

namespace vsgl {

CaptureCases::CaptureCases(Device& device, const TablesOptions& o, const Capture& capture,
                           std::vector<CaseBeyondDevice>* beyond)
    : camera_(upload_view(device, capture, ViewKind::kCamera)),
      light_(upload_view(device, capture, ViewKind::kLight)),
      runner_(device, o.timing) {
  for (const auto& g : o.generators)
    for (const DeviceView* view : {&camera_, &light_}) {
      GeneratorConfig cfg = o.generator;
      cfg.vsgl_count = view->kind == ViewKind::kCamera ? o.camera_vsgls : o.light_vsgls;
      try {
        std::unique_ptr<VsglGenerator> made = make_generator(g, device, *view, cfg);
        if (o.wrap_generator) made = o.wrap_generator(device, std::move(made));
        generators_.push_back(std::move(made));
      } catch (const DeviceLimitError& e) {
        if (beyond == nullptr) throw;
        beyond->push_back(CaseBeyondDevice{g, view_name(view->kind), e.what()});
        continue;
      }
      cases_.push_back(TimingCase{g, view_name(view->kind), generators_.back().get()});
      runner_.add(cases_.back());
    }
  if (generators_.empty() && beyond != nullptr && !beyond->empty())
    throw DeviceLimitError("no generator fits the device here: " + beyond->front().reason);
}

}  // namespace vsgl
