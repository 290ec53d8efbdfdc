#pragma once
/// Strict text-to-number conversion shared by the YAML and CSV readers: the whole text must be one
/// decimal number, and non-finite values ("nan", "inf") are refused, so a typo can never turn into
/// a NaN or a silently truncated value inside the model.
#include <cstdint>
#include <optional>
#include <string_view>

namespace bpm {

/// A finite double written in decimal or scientific notation ("0.4", "-1e5", "+2.5E-3").
std::optional<double> parse_double(std::string_view text);

/// A decimal integer ("11", "-3"); no fraction, exponent or leading zeros read as octal.
std::optional<std::int64_t> parse_int64(std::string_view text);

}  // namespace bpm
