// Internal to read_exr: decodes one part's pixels into an Image as an ExrChannelPlan says.
#pragma once

#include <ImfInputPart.h>
#include <ImathVec.h>

#include "exr_channels.hpp"
#include "exr_header_scan.hpp"
#include "image.hpp"

namespace pfx::app::detail {

// `img` has the display window's size, its rgba (unless the plan reads no colour) and depth (if
// the plan reads depth) already filled with "nothing there". `luminance_weights` turn Y, RY, BY
// into RGB. Throws what OpenEXR throws for damaged data.
void read_planned_pixels(Imf::InputPart& file, const ExrWindow& data, const ExrWindow& display,
                         const ExrChannelPlan& plan, const Imath::V3f& luminance_weights, Image* img);

}  // namespace pfx::app::detail
