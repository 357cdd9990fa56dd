// The table of contact laws; see contact_law.hpp.
#include "contact/contact_law.hpp"

#include "contact/hertz_law.hpp"
#include "contact/penalty_law.hpp"

#include <array>

namespace isosid::run {
namespace {

struct LawRow {
  const char* name;
  ContactLaw::Kind kind;
  std::unique_ptr<ContactLaw> (*make)(const ContactLawParameters&);
};

/// One row per law: the name scenes give, its kind, how it is built.
const std::array kLaws{
    LawRow{"penalty", ContactLaw::Kind::Pressure, [](const ContactLawParameters& p) -> std::unique_ptr<ContactLaw> {
             return std::make_unique<PenaltyLaw>(p.stiffness);
           }},
    LawRow{"hertz", ContactLaw::Kind::Point, [](const ContactLawParameters& p) -> std::unique_ptr<ContactLaw> {
             return std::make_unique<HertzLaw>(p.stiffness);
           }},
};

const LawRow* find(const std::string& name) {
  for (const LawRow& row : kLaws)
    if (name == row.name) return &row;
  return nullptr;
}

}  // namespace

std::unique_ptr<ContactLaw> make_contact_law(const std::string& name, const ContactLawParameters& p) {
  const LawRow* row = find(name);
  return row ? row->make(p) : nullptr;
}

std::optional<ContactLaw::Kind> contact_law_kind(const std::string& name) {
  const LawRow* row = find(name);
  if (!row) return std::nullopt;
  return row->kind;
}

std::vector<std::string> contact_law_names(ContactLaw::Kind kind) {
  std::vector<std::string> names;
  for (const LawRow& row : kLaws)
    if (row.kind == kind) names.emplace_back(row.name);
  return names;
}

}  // namespace isosid::run
