#pragma once
// "Did you mean ...?" suggestions for misspelt keys and names in input files.

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace momenta {

/// Edit distance between two strings: insertions, deletions, substitutions and transpositions of
/// adjacent characters ('wrold' is one edit from 'world'), each counting 1 (the optimal string
/// alignment distance, Damerau 1964). Case-insensitive.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `word`, if it is close enough to be a likely misspelling: within
/// an edit distance of max(1, |word| / 3). Case-insensitive.
std::optional<std::string> closest_match(std::string_view word,
                                         std::span<const std::string_view> candidates);

/// " (did you mean 'x'?)" when a close candidate exists, else "" — ready to append to a message.
std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace momenta
