#pragma once
// Validation of user parameter lists against the valid list a class publishes
// (Belos' getValidParameters convention): unknown names get a "did you mean" hint, wrong
// types and out-of-range values a message with the parameter's full path.
#include <initializer_list>
#include <string>
#include <utility>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

namespace signorini {

// Returns `valid` with the user's values put in, after checking them:
// - every user name must exist in `valid`, except inside sublists named "MueLu", "Belos"
//   or "Ifpack2", which are passed through to those packages unchanged;
// - a valid sublist holding a sublist named "<name>" accepts any number of user sublists
//   of any name, each validated against that template (e.g. one per boundary);
// - an int where a double is expected is accepted and converted, and a number where an
//   autoOrRange() parameter's "auto" stands;
// - validators attached to valid entries (ranges, string choices) are applied.
// `path` prefixes messages, e.g. "Problem". Throws InputError.
Teuchos::ParameterList validatedParameters(const Teuchos::ParameterList& user,
                                           const Teuchos::ParameterList& valid,
                                           const std::string& path);

// The validators of the valid lists. Each range rule lives in its parameter's validator, so
// that it holds wherever the parameter is read; acceptedValues() words it for messages.

// A number from lo to hi (an int parameter with T = int).
template <class T>
Teuchos::RCP<const Teuchos::EnhancedNumberValidator<T>> range(T lo, T hi) {
  return Teuchos::rcp(new Teuchos::EnhancedNumberValidator<T>(lo, hi));
}

// One of `names`, read as a string (names passed on to other packages, or read once into a
// definition).
Teuchos::RCP<const Teuchos::StringValidator> choices(std::initializer_list<std::string> names);

// One of the names of `options`, parsed once into its enum value: choice<Enum>(list, name).
template <class Enum>
Teuchos::RCP<const Teuchos::StringToIntegralParameterEntryValidator<Enum>> choices(
    std::initializer_list<std::pair<std::string, Enum>> options, const std::string& parameterName) {
  Teuchos::Array<std::string> names;
  Teuchos::Array<Enum> values;
  for (const auto& [name, value] : options) {
    names.push_back(name);
    values.push_back(value);
  }
  return Teuchos::rcp(new Teuchos::StringToIntegralParameterEntryValidator<Enum>(names, values, parameterName));
}

// The enum value of a choice parameter of a validated list (its entry carries the validator
// that choices() made).
template <class Enum>
Enum choice(const Teuchos::ParameterList& list, const std::string& name) {
  return Teuchos::getIntegralValue<Enum>(list, name);
}

namespace detail {

// 0 or an integer in [lo, hi]: a parameter whose 0 switches a feature off.
class ZeroOrRangeValidator : public Teuchos::ParameterEntryValidator {
 public:
  ZeroOrRangeValidator(int lo, int hi) : lo_(lo), hi_(hi) {}
  const std::string getXMLTypeName() const override { return "ZeroOrRangeValidator(int)"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& name,
                const std::string& sublist) const override;
  std::string description() const;

 private:
  int lo_, hi_;
};

// "auto", or a number from lo to hi (as a double, an int or a string).
class AutoOrRangeValidator : public Teuchos::ParameterEntryValidator {
 public:
  AutoOrRangeValidator(double lo, double hi) : lo_(lo), hi_(hi) {}
  const std::string getXMLTypeName() const override { return "AutoOrRangeValidator(double)"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& name,
                const std::string& sublist) const override;
  std::string description() const;
  // The entry's value as a number, if it is one (a string must hold nothing else).
  static bool number(const Teuchos::ParameterEntry& entry, double& value);

 private:
  double lo_, hi_;
};

}  // namespace detail

// 0, or an integer from lo to hi.
Teuchos::RCP<const detail::ZeroOrRangeValidator> zeroOrRange(int lo, int hi);

// "auto" (the reader picks the value from the context), or a number from lo to hi given as a
// double, an int or a string. The valid entry holds the string "auto"; read it with
// autoOrNumber().
Teuchos::RCP<const detail::AutoOrRangeValidator> autoOrRange(double lo, double hi);

// The number of a validated autoOrRange() parameter, or `automatic` when it is "auto".
double autoOrNumber(const Teuchos::ParameterList& list, const std::string& name, double automatic);

// Expert parameters: signorini --defaults leaves them out, xml/defaults.xml and
// doc/parameters.md mark them. A Teuchos entry holds a value, a documentation string and a
// validator, and keeps them through copies and validation; so the mark is carried by the
// validator: expert(v) is v marked (it still validates, and names its rule, as v does),
// expert() the mark alone, for a parameter without other rules.
class ExpertMark {
 public:
  virtual ~ExpertMark() = default;
};

namespace detail {

template <class Validator>
class Expert final : public Validator, public ExpertMark {
 public:
  explicit Expert(const Validator& validator) : Validator(validator) {}
};

}  // namespace detail

template <class Validator>
Teuchos::RCP<const Validator> expert(const Teuchos::RCP<const Validator>& validator) {
  return Teuchos::rcp(new detail::Expert<Validator>(*validator));
}
Teuchos::RCP<const Teuchos::ParameterEntryValidator> expert();
bool isExpert(const Teuchos::ParameterEntry& entry);

// What a validator accepts, in words: "a number from 0 to 0.4999", "one of "a", "b"".
std::string acceptedValues(const Teuchos::ParameterEntryValidator& validator);

// Name of the template sublist for user-named entries.
inline const char* kAnyNameSublist = "<name>";

// The candidate closest to `name` by edit distance, or "" if none is reasonably close.
std::string closestName(const std::string& name, const Teuchos::ParameterList& valid);

}  // namespace signorini
