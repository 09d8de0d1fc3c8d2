// The temporary files of AtomicFile and the temporary folders of OutputFolder that exist
// right now, kept where a signal handler can remove them (fixed slots, no allocation):
// SIGINT, SIGTERM or SIGHUP then ends the process as it would have, minus the hidden
// temporaries.
#pragma once

#include <signal.h>

#include <string>

namespace tierlift::io::detail {

// mkstemp(pattern) with the signals blocked until the name is registered. The slot, or -1
// with *err set (errno of the failure, or EMFILE when every slot is taken).
int create_registered_temp(const std::string& pattern, int* fd, int* err);
// mkdtemp(pattern), registered the same way: a signal empties and removes the folder (its
// plain files; a temporary folder holds nothing else).
int create_registered_temp_dir(const std::string& pattern, int* err);
std::string registered_temp_name(int slot);
// rename(temp, target) and unregister, as one step as far as the signals are concerned.
// Files and folders alike.
bool rename_registered_temp(int slot, const std::string& target, int* err);
// Unregisters the slot, removing its file (or its folder and what is in it) first when
// `remove`.
void remove_registered_temp(int slot, bool remove);

// Holds SIGINT, SIGTERM and SIGHUP back for its lifetime (this thread): a group of renames
// made under it is finished before an interrupt ends the process.
class SignalsBlocked {
public:
  SignalsBlocked();
  ~SignalsBlocked();
  SignalsBlocked(const SignalsBlocked&) = delete;
  SignalsBlocked& operator=(const SignalsBlocked&) = delete;

private:
  sigset_t old_;
};

} // namespace tierlift::io::detail
