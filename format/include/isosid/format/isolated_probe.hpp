// A first read of an untrusted file in a child process. libhdf5 trusts the metadata it reads:
// a corrupt B-tree or heap can make it crash or allocate without bound before any of our
// checks runs. The child reads the whole file once; if it is killed by a signal, runs out of
// its memory allowance or hangs, the file is reported as corrupt and the program goes on.
#pragma once
#include <functional>
#include <string>

namespace isosid::format {

/// Memory a probe may use beyond what the program already holds, bytes.
constexpr long long kProbeMemoryBytes = 1LL << 30;
/// Seconds a probe may take before the file counts as hanging libhdf5.
constexpr int kProbeSeconds = 60;

/// Runs `read` (which throws InputError on a bad but intact file) in a forked child. Returns
/// normally when the child finished, with or without InputError (the caller then reads the
/// file itself and reports any error with its own message). Throws InputError naming `path`
/// when the child crashed, exhausted its memory or hung.
void probe_in_child(const std::string& path, const std::function<void()>& read);

}  // namespace isosid::format
