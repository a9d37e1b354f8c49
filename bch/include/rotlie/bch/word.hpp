#pragma once
// Words over an alphabet {0, 1, …} (letter 0 < letter 1 < …), Lyndon words and their
// standard bracketing, the basis in which Lie series are stored.
#include <cstdint>
#include <string>
#include <vector>

namespace rotlie::bch {

using word = std::vector<std::uint8_t>;

/// Whether w is a Lyndon word: strictly smaller than each of its proper rotations.
bool is_lyndon(const word& w);

/// All Lyndon words of length 1 … max_length over `letters` letters, ordered by length, then
/// lexicographically (Fredricksen–Kessler–Maiorana generation).
std::vector<word> lyndon_words(int letters, int max_length);

/// Standard factorisation w = u v of a Lyndon word of length ≥ 2: v is its longest proper Lyndon suffix.
/// The basis element is then P_w = [P_u, P_v].
std::pair<word, word> standard_factorization(const word& w);

/// "[A,[A,B]]"-style text of P_w, letters named A, B, C, … .
std::string bracket_text(const word& w);

}  // namespace rotlie::bch
