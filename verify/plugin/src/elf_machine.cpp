#include "elf_machine.hpp"

#include <elf.h>

#include <cstdint>
#include <fstream>

namespace fdh::verify::plugin {
namespace {

#if defined(__x86_64__)
constexpr int kMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr int kMachine = EM_AARCH64;
#elif defined(__i386__)
constexpr int kMachine = EM_386;
#elif defined(__arm__)
constexpr int kMachine = EM_ARM;
#elif defined(__powerpc64__)
constexpr int kMachine = EM_PPC64;
#elif defined(__riscv)
constexpr int kMachine = EM_RISCV;
#elif defined(__s390x__)
constexpr int kMachine = EM_S390;
#else
constexpr int kMachine = -1;  // unknown: never called wrong
#endif
constexpr unsigned char kClass = sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32;

std::string machine_name(int m) {
  switch (m) {
    case EM_X86_64:
      return "x86-64";
    case EM_AARCH64:
      return "aarch64";
    case EM_386:
      return "i386";
    case EM_ARM:
      return "32-bit arm";
    case EM_PPC64:
      return "ppc64";
    case EM_RISCV:
      return "risc-v";
    case EM_S390:
      return "s390";
  }
  return "another machine";
}

}  // namespace

std::string wrong_machine(const std::string& file) {
  unsigned char h[20];  // e_ident (16 bytes), e_type (2), e_machine (2): the same in both classes
  std::ifstream in(file, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(h), sizeof h)) return "";
  if (h[EI_MAG0] != ELFMAG0 || h[EI_MAG1] != ELFMAG1 || h[EI_MAG2] != ELFMAG2 ||
      h[EI_MAG3] != ELFMAG3)
    return "";
  const int machine = h[EI_DATA] == ELFDATA2MSB ? h[18] << 8 | h[19] : h[19] << 8 | h[18];
  const std::string bits = h[EI_CLASS] == ELFCLASS64 ? "64-bit " : "32-bit ";
  if (kMachine < 0 || (machine == kMachine && h[EI_CLASS] == kClass)) return "";
  return "it is built for " + bits + machine_name(machine) + " (ELF machine " +
         std::to_string(machine) + "), but this fdhcert runs on " +
         (kClass == ELFCLASS64 ? "64-bit " : "32-bit ") + machine_name(kMachine);
}

std::string not_loaded(const std::string& file, const std::string& dlerror_words) {
  const std::string machine = wrong_machine(file);
  return machine.empty() ? dlerror_words : machine + " (dlerror: " + dlerror_words + ")";
}

}  // namespace fdh::verify::plugin
