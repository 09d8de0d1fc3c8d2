// The temporary files of AtomicFile that exist right now, kept where a signal handler can
// remove them (fixed slots, no allocation): SIGINT, SIGTERM or SIGHUP then ends the process
// as it would have, minus the hidden temporary files.
#pragma once

#include <string>

namespace tierlift::io::detail {

// mkstemp(pattern) with the signals blocked until the name is registered. The slot, or -1
// with *err set (errno of the failure, or EMFILE when every slot is taken).
int create_registered_temp(const std::string& pattern, int* fd, int* err);
std::string registered_temp_name(int slot);
// rename(temp, target) and unregister, as one step as far as the signals are concerned.
bool rename_registered_temp(int slot, const std::string& target, int* err);
// Unregisters the slot, unlinking its file first when `unlink_file`.
void remove_registered_temp(int slot, bool unlink_file);

} // namespace tierlift::io::detail
