#include "core/ParameterValidation.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

bool isPassThrough(const std::string& name) { return name == "MueLu" || name == "Belos" || name == "Ifpack2"; }

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t above = row[j];
      bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string join(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "/" + name;
}

std::string validNames(const Teuchos::ParameterList& valid) {
  std::ostringstream out;
  bool first = true;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    if (valid.name(it) == kAnyNameSublist) continue;
    out << (first ? "" : ", ") << '"' << valid.name(it) << '"';
    first = false;
  }
  return out.str();
}

void validateInto(const Teuchos::ParameterList& user, Teuchos::ParameterList& merged,
                  const std::string& path) {
  const bool anyName = merged.isSublist(kAnyNameSublist);
  const Teuchos::ParameterList templ = anyName ? merged.sublist(kAnyNameSublist) : Teuchos::ParameterList();
  if (anyName) merged.remove(kAnyNameSublist);

  for (auto it = user.begin(); it != user.end(); ++it) {
    const std::string& name = user.name(it);
    const Teuchos::ParameterEntry& entry = user.entry(it);
    const std::string where = join(path, name);

    // A list with a template takes a sublist of any other name than its own entries'.
    if (anyName && !merged.isParameter(name) && (entry.isList() || merged.numParams() == 0)) {
      if (!entry.isList())
        throw InputError(where + ": expected a sublist (one per named item)");
      Teuchos::ParameterList sub = templ;
      sub.setName(name);
      validateInto(Teuchos::getValue<Teuchos::ParameterList>(entry), sub, where);
      merged.set(name, sub);
      continue;
    }
    if (!merged.isParameter(name)) {
      std::string hint = closestName(name, merged);
      throw InputError(where + (entry.isList() ? ": unknown sublist" : ": unknown parameter") +
                       (hint.empty() ? std::string(".") : "; did you mean \"" + hint + "\"?") +
                       " Valid names here: " + validNames(merged));
    }
    Teuchos::ParameterEntry& target = merged.getEntry(name);
    if (target.isList()) {
      if (!entry.isList()) throw InputError(where + ": expected a sublist");
      if (isPassThrough(name)) {
        target.setValue(Teuchos::getValue<Teuchos::ParameterList>(entry));
      } else {
        validateInto(Teuchos::getValue<Teuchos::ParameterList>(entry), merged.sublist(name), where);
      }
      continue;
    }
    if (entry.isList()) throw InputError(where + ": expected a value, not a sublist");

    Teuchos::ParameterEntry value = entry;
    const auto& expected = target.getAny(false).type();
    // A number stands where an autoOrRange() parameter's "auto" does; its validator checks it.
    const bool numberForAuto = dynamic_cast<const detail::AutoOrRangeValidator*>(target.validator().get()) &&
                               (value.isType<double>() || value.isType<int>());
    if (value.getAny(false).type() != expected && !numberForAuto) {
      if (expected == typeid(double) && value.isType<int>()) {
        value.setValue(static_cast<double>(Teuchos::getValue<int>(value)));
      } else {
        throw InputError(where + ": has type " + value.getAny(false).typeName() +
                         ", expected " + target.getAny(false).typeName());
      }
    }
    if (auto validator = target.validator(); !validator.is_null()) {
      try {
        validator->validate(value, name, path.empty() ? "top level" : path);
      } catch (const std::exception&) {
        throw InputError(where + ": invalid value " + Teuchos::toString(value.getAny(false)) +
                         "; accepted: " + acceptedValues(*validator));
      }
    }
    value.setValidator(target.validator());
    value.setDocString(target.docString());
    target = value;
  }
}

// Templates of user-named sublists are not parameters: drop those the user did not use.
void removeTemplates(Teuchos::ParameterList& list) {
  if (list.isSublist(kAnyNameSublist)) list.remove(kAnyNameSublist);
  for (auto it = list.begin(); it != list.end(); ++it)
    if (list.entry(it).isList() && !isPassThrough(list.name(it)))
      removeTemplates(list.sublist(list.name(it)));
}

std::string quotedList(const Teuchos::Array<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
  return list;
}

}  // namespace

Teuchos::RCP<const Teuchos::StringValidator> choices(std::initializer_list<std::string> names) {
  return Teuchos::rcp(new Teuchos::StringValidator(Teuchos::Array<std::string>(names)));
}

namespace detail {

void ZeroOrRangeValidator::printDoc(const std::string& docString, std::ostream& out) const {
  out << "# " << docString << "\n# " << description() << "\n";
}

void ZeroOrRangeValidator::validate(const Teuchos::ParameterEntry& entry, const std::string& name,
                                    const std::string& sublist) const {
  const int value = entry.isType<int>() ? Teuchos::getValue<int>(entry) : -1;
  if (!entry.isType<int>() || (value != 0 && (value < lo_ || value > hi_)))
    throw Teuchos::Exceptions::InvalidParameterValue(sublist + "/" + name + ": " + description());
}

std::string ZeroOrRangeValidator::description() const {
  return "0, or an integer from " + std::to_string(lo_) + " to " + std::to_string(hi_);
}

void AutoOrRangeValidator::printDoc(const std::string& docString, std::ostream& out) const {
  out << "# " << docString << "\n# " << description() << "\n";
}

void AutoOrRangeValidator::validate(const Teuchos::ParameterEntry& entry, const std::string& name,
                                    const std::string& sublist) const {
  if (entry.isType<std::string>() && Teuchos::getValue<std::string>(entry) == "auto") return;
  double value = 0;
  if (!number(entry, value) || value < lo_ || value > hi_)
    throw Teuchos::Exceptions::InvalidParameterValue(sublist + "/" + name + ": " + description());
}

std::string AutoOrRangeValidator::description() const {
  std::ostringstream out;
  out << "\"auto\", or a number from " << lo_ << " to " << hi_;
  return out.str();
}

bool AutoOrRangeValidator::number(const Teuchos::ParameterEntry& entry, double& value) {
  if (entry.isType<double>()) value = Teuchos::getValue<double>(entry);
  else if (entry.isType<int>()) value = Teuchos::getValue<int>(entry);
  else if (!entry.isType<std::string>()) return false;
  else {
    std::istringstream in(Teuchos::getValue<std::string>(entry));
    if (!(in >> value) || !(in >> std::ws).eof()) return false;
  }
  return true;
}

// The mark alone: any value of the parameter's type (validatedParameters checks the type).
class ExpertOnly final : public Teuchos::ParameterEntryValidator, public ExpertMark {
 public:
  const std::string getXMLTypeName() const override { return "ExpertParameter"; }
  void printDoc(const std::string& docString, std::ostream& out) const override { out << "# " << docString << "\n"; }
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry&, const std::string&, const std::string&) const override {}
};

}  // namespace detail

Teuchos::RCP<const detail::ZeroOrRangeValidator> zeroOrRange(int lo, int hi) {
  return Teuchos::rcp(new detail::ZeroOrRangeValidator(lo, hi));
}

Teuchos::RCP<const detail::AutoOrRangeValidator> autoOrRange(double lo, double hi) {
  return Teuchos::rcp(new detail::AutoOrRangeValidator(lo, hi));
}

Teuchos::RCP<const Teuchos::ParameterEntryValidator> expert() { return Teuchos::rcp(new detail::ExpertOnly()); }

bool isExpert(const Teuchos::ParameterEntry& entry) {
  return dynamic_cast<const ExpertMark*>(entry.validator().get()) != nullptr;
}

double autoOrNumber(const Teuchos::ParameterList& list, const std::string& name, double automatic) {
  const Teuchos::ParameterEntry& entry = list.getEntry(name);
  if (entry.isType<std::string>() && Teuchos::getValue<std::string>(entry) == "auto") return automatic;
  double value = 0;
  if (!detail::AutoOrRangeValidator::number(entry, value))
    throw Error(name + ": \"auto\" or a number expected (the list was not validated)");
  return value;
}

std::string acceptedValues(const Teuchos::ParameterEntryValidator& validator) {
  std::ostringstream out;
  if (auto* real = dynamic_cast<const Teuchos::EnhancedNumberValidator<double>*>(&validator)) {
    out << "a number from " << real->getMin() << " to " << real->getMax();
  } else if (auto* integer = dynamic_cast<const Teuchos::EnhancedNumberValidator<int>*>(&validator)) {
    out << "an integer from " << integer->getMin() << " to " << integer->getMax();
  } else if (auto* zeroOr = dynamic_cast<const detail::ZeroOrRangeValidator*>(&validator)) {
    out << zeroOr->description();
  } else if (auto* autoOr = dynamic_cast<const detail::AutoOrRangeValidator*>(&validator)) {
    out << autoOr->description();
  } else if (const auto names = validator.validStringValues(); !names.is_null()) {
    out << (names->size() == 1 ? "" : "one of ") << quotedList(*names);
  } else {
    validator.printDoc("", out);
    std::string doc = out.str();
    while (!doc.empty() && (doc.back() == '\n' || doc.back() == ' ')) doc.pop_back();
    std::replace(doc.begin(), doc.end(), '\n', ' ');
    return doc;
  }
  return out.str();
}

std::string closestName(const std::string& name, const Teuchos::ParameterList& valid) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(3, name.size() / 3) + 1;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    std::size_t d = editDistance(name, valid.name(it));
    if (d < bestDistance) {
      bestDistance = d;
      best = valid.name(it);
    }
  }
  return best;
}

Teuchos::ParameterList validatedParameters(const Teuchos::ParameterList& user,
                                           const Teuchos::ParameterList& valid,
                                           const std::string& path) {
  Teuchos::ParameterList merged = valid;
  validateInto(user, merged, path);
  removeTemplates(merged);
  return merged;
}

}  // namespace signorini
