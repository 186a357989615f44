#pragma once
// Small text tools for the offline interpreter: normalised words, phrase search, numbers
// written as digits or words ("two", "half a metre", "1.5").
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace chatsim::agents::text {

// Lower case; letters, digits, '.', '-' kept inside words; everything else separates words.
// British and American spellings are folded ("metres" -> "meters"), abbreviations written out
// ("lhs" -> "left side", "w/" -> "with"), and '&' read as "and".
std::vector<std::string> words(std::string_view s);
std::string join(const std::vector<std::string>& words, size_t begin = 0, size_t end = std::string::npos);
// Words said with a capital after the sentence's first word ("add a Lada Niva"), lower-cased: names.
std::set<std::string> capitalised_words(std::string_view sentence);

// Index of the first occurrence of a phrase ("turn left") at or after `from`, or npos.
size_t find_phrase(const std::vector<std::string>& w, std::string_view phrase, size_t from = 0);
// As find_phrase, for a phrase already split into words (a table read once, searched often).
size_t find_words(const std::vector<std::string>& w, const std::vector<std::string>& phrase, size_t from = 0);
bool has_phrase(const std::vector<std::string>& w, std::string_view phrase);
bool has_any(const std::vector<std::string>& w, std::initializer_list<std::string_view> phrases);
// Index of the first phrase found (by position in the text), or npos.
size_t find_any(const std::vector<std::string>& w, std::initializer_list<std::string_view> phrases,
                size_t* length = nullptr);

// A number written as digits or words at w[i] ("5", "five", "twenty five", "a", "half", "1.5").
// On success sets `used` to how many words it took.
std::optional<double> number_at(const std::vector<std::string>& w, size_t i, size_t* used = nullptr);

// A quantity followed by one of the units, e.g. "5 m", "half a meter", "30 degrees": returns the
// value and the index after the unit.
struct Quantity {
  double value = 0;
  size_t begin = 0;   // first word of the number
  size_t end = 0;     // one past the unit
  std::string unit;   // as listed ("m", "car lengths")
};
std::vector<Quantity> quantities(const std::vector<std::string>& w, std::initializer_list<std::string_view> units);
std::vector<Quantity> quantities(const std::vector<std::string>& w, const std::vector<std::string_view>& units);

// The units of length a command may say a distance in, and metres per unit (nullopt for a word
// that is none of them).
const std::vector<std::string_view>& length_units();
std::optional<double> meters_per(std::string_view unit);

bool is_number_word(const std::string& w);
// "first" .. "tenth" -> 1 .. 10 ("2nd" reaches readers as "second"); 0 for any other word.
int ordinal_value(const std::string& w);

// Amounts said as fractions of a turn ("a quarter turn", "half a turn", "a right angle") become
// degrees ("90 degrees") so that every agent reads them as angles.
void turns_to_degrees(std::vector<std::string>& w);

// A bare number after a verb that turns ("rotate left by 45", "pan 20 to the right") is an
// angle: "degrees" is put after it.
void bare_turns_to_degrees(std::vector<std::string>& w);

}  // namespace chatsim::agents::text
