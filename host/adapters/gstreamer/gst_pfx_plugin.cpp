// libgstpfx.so: the GStreamer plugin holding pfxfilter (docs/hosts.md).
#include <gst/gst.h>

#include "pfx_filter.hpp"

#ifndef PACKAGE
#define PACKAGE "pfx"
#endif

namespace {

gboolean plugin_init(GstPlugin* plugin) {
  return gst_element_register(plugin, "pfxfilter", GST_RANK_NONE, GST_TYPE_PFX_FILTER);
}

}  // namespace

// The licence is LICENSE's; "MIT/X11" is how GStreamer's list of licences spells MIT.
GST_PLUGIN_DEFINE(GST_VERSION_MAJOR, GST_VERSION_MINOR, pfx, "pfx post effects on GStreamer's OpenGL context",
                  plugin_init, PFX_VERSION, "MIT/X11", "pfx", PFX_ORIGIN_URL)
