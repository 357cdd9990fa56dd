// The table of reduction methods (format/reduction_method.hpp) that model files, the
// reduction, the SID builder and the runtime share.
#include "isosid/format/reduction_method.hpp"
#include "isosid/format/sid.hpp"

#include <catch2/catch.hpp>
#include <set>

using namespace isosid::format;

TEST_CASE("reduction methods: one row per method, each name read back as its method, SIDs told massless by their name", "[format][unit]") {
  std::set<std::string_view> names;
  for (const ReductionMethodTraits& t : kReductionMethods) {
    CHECK(names.insert(t.name).second);  // names are unique
    CHECK(reduction_method_named(t.name) == t.method);
    CHECK(&traits(t.method) == &t);
    RefMod r;
    r.reduction_method = std::string(t.name);
    CHECK(r.massless_boundary() == t.massless_boundary);
    // a massless boundary has no interface nodes of its own: its boundary is the interface
    CHECK_FALSE((t.massless_boundary && t.interface_nodes));
  }
  CHECK(names.size() == 5);
  // SIDs from elsewhere, and the runtime's rigid bodies, name other methods
  CHECK_FALSE(reduction_method_named("rigid").has_value());
  RefMod rigid;
  rigid.reduction_method = "rigid";
  CHECK_FALSE(rigid.massless_boundary());
  CHECK(reduction_method_names() == "modal, craig-bampton, full, macneal or craig-bampton-massless");
  CHECK(reduction_method_names([](const ReductionMethodTraits& t) { return t.interface_nodes; }, "\"") == "\"craig-bampton\"");
}
