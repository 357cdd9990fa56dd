// A first read of an untrusted file in a child process. libhdf5 trusts the metadata it reads:
// a corrupt B-tree or heap can make it crash or allocate without bound before any of our
// checks runs. The child reads the whole file once, under a memory allowance that scales with
// the file's size; if it is killed by a signal, runs out of its allowance or hangs, the file is
// reported as corrupt. If it finds bad input, its message is the program's, and the parent
// never touches the file.
#pragma once
#include <cstdint>
#include <functional>
#include <string>

// Under AddressSanitizer the probe sets no memory limit (ASan reserves terabytes of address
// space up front); tests that measure the probe's memory ask this too.
#if defined(__SANITIZE_ADDRESS__)
#define ISOSID_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ISOSID_UNDER_ASAN 1
#endif
#endif

namespace isosid::format {

/// Memory a probe may use beyond what the program already holds and beyond 3x the data the
/// file can hold (h5::most_data_bytes: the data read, its copy, and room to spare), bytes.
constexpr long long kProbeBaseMemoryBytes = 128LL << 20;
/// Seconds a probe may take on any file before it counts as hanging libhdf5, and the read rate
/// beyond which more time is allowed for a large file (libhdf5 reads and inflates SIDs at
/// 100+ MB/s here; a corrupt B-tree can make it loop for ever).
constexpr int kProbeBaseSeconds = 10;
constexpr double kProbeSlowestBytesPerSecond = 10e6;

/// The memory allowance of a probe reading a file of `file_bytes`, beyond what the program holds.
long long probe_memory_bytes(std::uintmax_t file_bytes);
/// The time a probe may take on a file of `file_bytes`, s.
int probe_seconds(std::uintmax_t file_bytes);

/// Runs `read` in a forked child. Returns normally when the child read the file without error
/// (the caller then reads it itself, within the memory the child needed). Throws the child's
/// InputError when it found bad input, and InputError naming `path` when it crashed, exhausted
/// its memory allowance or hung.
void probe_in_child(const std::string& path, const std::function<void()>& read);

/// Probes this process has started (tests count them).
long probes_started();

}  // namespace isosid::format
