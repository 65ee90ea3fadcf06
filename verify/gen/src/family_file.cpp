#include "fdh/gen/family_file.hpp"

#include "fdh/gen/case_seed.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/io/query_io.hpp"
#include "fdh/os/atomic_file.hpp"

namespace fdh::verify {

void write_family_file(const std::string& family, long count, std::uint64_t seed,
                       const std::string& path) {
  const Family* f = family_named(family);
  AtomicFile file(path);  // written as generated, published whole by commit()
  std::ostream& os = file.stream();
  os << "# fdhcert generate " << family << " --count " << count << " --seed " << seed << "\n";
  double min_distance = 0;  // the stream's δ: a δ family's cases each carry their own
  for (long i = 0; i < count; ++i) {
    QueryRecord r = generate(*f, case_seed(seed, i)).record();
    r.id = family + "/" + std::to_string(i);
    write_native(os, r, min_distance);
  }
  file.commit();
}

}  // namespace fdh::verify
