// The exit codes of pfx's programs, defined once here; docs/exit-codes.md is the table users
// read, program by program. Most programs share the first five. A few codes mean something of
// their own to one program (said beside each), and pfx-farm, a Python script, keeps the same
// numbers as constants of its own. A signal that stops a program gives 128 + the signal, as
// shells report it.
#pragma once

namespace pfx::exit_code {

constexpr int kOk = 0;
constexpr int kInternal = 1;     // no OpenGL 4.5 context, an output that cannot be written, out of memory
constexpr int kUsage = 2;        // a bad option or value (the message names it)
constexpr int kBadInput = 3;     // an input file missing, unreadable or malformed
constexpr int kEffectError = 4;  // a plugin, effect or importer failed, or is not loaded

// pfx-render --frames: some frames failed; the others were written.
constexpr int kSomeFramesFailed = 5;

// pfx-validate: a check failed (the plugin's fault, not the validator's).
constexpr int kCheckFailed = 1;

// A program stopped by a signal after finishing what it was doing: 128 + the signal (130 for
// SIGINT, 143 for SIGTERM).
constexpr int kSignalBase = 128;

// pfx-inject's own codes. The application's own code passes through pfx-inject unchanged, so
// these sit where applications and shells do not: 0-125 are the application's, 126 and 127 the
// shell's, 128 + N a signal (N up to 64), 255 an exit(-1).
constexpr int kInjectUsage = 240;       // a bad option, chain, preset, --set or capture
constexpr int kInjectSetup = 241;       // libpfxinject.so or every effect plugin missing
constexpr int kInjectNotStarted = 242;  // the application could not be started
constexpr int kInjectBench = 243;       // --bench measured nothing, or could not write its results

}  // namespace pfx::exit_code
