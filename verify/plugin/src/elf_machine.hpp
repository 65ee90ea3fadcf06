// Why a shared library that exists does not load: dlerror says "No such file or directory" for
// an aarch64 library on x86-64 (the loader looked for it in the wrong place). The ELF header's
// class and e_machine say it plainly.
#pragma once

#include <string>

namespace fdh::verify::plugin {

// "it is built for aarch64 (ELF machine 183), but this fdhcert runs on x86-64" when `file` is an
// ELF file of another machine or class; "" otherwise (also when it cannot be read).
std::string wrong_machine(const std::string& file);

// Why `file` did not load: dlerror's words, or the ELF header's where dlerror misleads.
std::string not_loaded(const std::string& file, const std::string& dlerror_words);

}  // namespace fdh::verify::plugin
