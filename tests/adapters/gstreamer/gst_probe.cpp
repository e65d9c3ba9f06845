// gst_probe: a small GStreamer application for the pfxfilter tests. It runs a gst-launch style
// pipeline to its end, as an application embedding GStreamer would, and does things at given
// buffers of one element's sink pad:
//   gst_probe PIPELINE [--at ELEMENT] [--set N PROPERTY VALUE]... [--rss N]...
//     --at ELEMENT          the element whose sink pad counts buffers (default "fx")
//     --set N P V           before buffer N (from 0) reaches the element, sets its property P to V
//                           (from the streaming thread, as a live control would)
//     --rss N               once buffer N has passed the element, prints "rss N BYTES": the
//                           process's resident anonymous memory (RssAnon)
// At the end it prints "buffers N" and "handed on as they came: I,J,...": the buffers (from 0)
// that left the element as the very buffer that entered it (a passthrough: no new frame drawn).
// Exit code 0 at the end of the stream, 1 with the error message on a pipeline error, 2 on usage.
// Run with the environment of host_programs.hpp, like the hosts.
#include <gst/gst.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct Change {
  long buffer;
  std::string property, value;
};

struct Probe {
  GstElement* element = nullptr;
  std::vector<Change> changes;
  std::vector<long> rss_at;
  long buffers = 0;
  GstBuffer* entered = nullptr;  // the buffer that last reached the sink pad, compared, not used
  std::string untouched;         // the buffers that left as they entered, comma-separated
};

unsigned long long rss_anon_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("RssAnon:", 0) == 0) return std::stoull(line.substr(8)) * 1024;
  return 0;
}

GstPadProbeReturn before_buffer(GstPad*, GstPadProbeInfo* info, gpointer data) {
  auto* probe = static_cast<Probe*>(data);
  probe->entered = GST_PAD_PROBE_INFO_BUFFER(info);
  for (const auto& change : probe->changes)
    if (change.buffer == probe->buffers)
      gst_util_set_object_arg(G_OBJECT(probe->element), change.property.c_str(), change.value.c_str());
  return GST_PAD_PROBE_OK;
}

GstPadProbeReturn after_buffer(GstPad*, GstPadProbeInfo* info, gpointer data) {
  auto* probe = static_cast<Probe*>(data);
  if (GST_PAD_PROBE_INFO_BUFFER(info) == probe->entered)
    probe->untouched += (probe->untouched.empty() ? "" : ",") + std::to_string(probe->buffers);
  for (long at : probe->rss_at)
    if (at == probe->buffers) std::printf("rss %ld %llu\n", at, rss_anon_bytes());
  ++probe->buffers;
  return GST_PAD_PROBE_OK;
}

int usage() {
  std::fputs("usage: gst_probe PIPELINE [--at ELEMENT] [--set N PROPERTY VALUE]... [--rss N]...\n", stderr);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  gst_init(&argc, &argv);
  if (argc < 2) return usage();
  Probe probe;
  std::string at = "fx";
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--at" && i + 1 < argc) at = argv[++i];
    else if (arg == "--set" && i + 3 < argc) {
      probe.changes.push_back({std::atol(argv[i + 1]), argv[i + 2], argv[i + 3]});
      i += 3;
    } else if (arg == "--rss" && i + 1 < argc) probe.rss_at.push_back(std::atol(argv[++i]));
    else return usage();
  }
  GError* error = nullptr;
  GstElement* pipeline = gst_parse_launch(argv[1], &error);
  if (!pipeline) {
    std::fprintf(stderr, "gst_probe: %s\n", error ? error->message : "the pipeline does not parse");
    return 2;
  }
  probe.element = gst_bin_get_by_name(GST_BIN(pipeline), at.c_str());
  if (probe.element) {
    GstPad* sink = gst_element_get_static_pad(probe.element, "sink");
    GstPad* src = gst_element_get_static_pad(probe.element, "src");
    gst_pad_add_probe(sink, GST_PAD_PROBE_TYPE_BUFFER, before_buffer, &probe, nullptr);
    gst_pad_add_probe(src, GST_PAD_PROBE_TYPE_BUFFER, after_buffer, &probe, nullptr);
    gst_object_unref(sink);
    gst_object_unref(src);
  }
  gst_element_set_state(pipeline, GST_STATE_PLAYING);
  GstBus* bus = gst_element_get_bus(pipeline);
  int code = 0;
  for (bool done = false; !done;) {
    GstMessage* message = gst_bus_timed_pop_filtered(
        bus, GST_CLOCK_TIME_NONE, static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR | GST_MESSAGE_WARNING));
    if (GST_MESSAGE_TYPE(message) == GST_MESSAGE_WARNING) {
      GError* warning = nullptr;
      gst_message_parse_warning(message, &warning, nullptr);
      std::fprintf(stderr, "gst_probe: warning: %s\n", warning->message);
      g_error_free(warning);
    } else {
      if (GST_MESSAGE_TYPE(message) == GST_MESSAGE_ERROR) {
        GError* failure = nullptr;
        gst_message_parse_error(message, &failure, nullptr);
        std::fprintf(stderr, "gst_probe: error: %s\n", failure->message);
        g_error_free(failure);
        code = 1;
      }
      done = true;
    }
    gst_message_unref(message);
  }
  std::printf("buffers %ld\n", probe.buffers);
  std::printf("handed on as they came: %s\n", probe.untouched.c_str());
  gst_element_set_state(pipeline, GST_STATE_NULL);
  if (probe.element) gst_object_unref(probe.element);
  gst_object_unref(bus);
  gst_object_unref(pipeline);
  return code;
}
