// pfxfilter: the GStreamer GL element (a GstGLFilter) that runs a chain of pfx effects over
// video frames on GStreamer's own GL context. Properties chain, set, transfer and preset, as
// the frei0r plugin pfx_chain's parameters (chain_settings.hpp), changeable while it plays.
#pragma once

#include <gst/gl/gl.h>

G_BEGIN_DECLS

#define GST_TYPE_PFX_FILTER (gst_pfx_filter_get_type())
G_DECLARE_FINAL_TYPE(GstPfxFilter, gst_pfx_filter, GST, PFX_FILTER, GstGLFilter)

G_END_DECLS
