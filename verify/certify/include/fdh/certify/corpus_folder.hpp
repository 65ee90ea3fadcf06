// Where certify and report find the corpus when --corpus is not given (issue 24, "certify
// anywhere"): the source checkout's corpus when run from one, else the corpus installed with the
// program.
#pragma once

#include <string>

namespace fdh::verify {

// `given` when it names a folder (non-empty); otherwise ./corpus when it is a folder (run from a
// source checkout), else the installed corpus, FDH_CORPUS_FROM_BINDIR from the folder of the
// running program (/usr/bin/fdhcert -> /usr/share/fdhcert/corpus). Neither: a UsageError
// naming both places.
std::string corpus_or_default(const std::string& given);

}  // namespace fdh::verify
