// Words of polygonal schemata and the classical cut-and-paste normalization (e.g. Massey,
// "Algebraic Topology: An Introduction", ch. 1 §7), on words alone: a polygon's sides in boundary
// order, each a letter that appears once per side (paired sides once as x, once as x^-1; border
// sides once). The plan lists the moves that bring every handle into a commutator x y x^-1 y^-1;
// the topology module carries them out on a mesh (internal/canonical_schema_impl.h). Not for direct
// use.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tessera {
namespace internal {

/// One side of a polygon: `letter` (an id) read forwards or, when `inverse`, backwards.
struct Signed_letter {
  std::size_t letter = 0;
  bool inverse = false;
  friend bool operator==(const Signed_letter& a, const Signed_letter& b) {
    return a.letter == b.letter && a.inverse == b.inverse;
  }
  friend bool operator!=(const Signed_letter& a, const Signed_letter& b) { return !(a == b); }
};
using Schema_word = std::vector<Signed_letter>;

/// One cut-and-paste move on a polygon with boundary word w (corner i is where side w[i] starts):
/// cut along a new diagonal `letter`, running from corner `from` to corner `to` (0 <= from < to,
/// 2 <= to - from <= |w| - 2, `to` taken modulo |w|), which splits the polygon into the pieces
/// w[from, to) and w[to, from + |w|); then glue the two pieces back along the side pair `glue`,
/// which has one side in each piece.
struct Cut_and_paste_move {
  std::size_t from = 0, to = 0, glue = 0, letter = 0;
};

/// The word after `move`. Piece 1 is w[from, to) followed by the diagonal backwards, piece 2 is
/// w[to, from + n) followed by the diagonal forwards (each piece on the left of its boundary).
/// Gluing piece 1 = g A' to piece 2 = B' g^-1 along g gives B' A'.
inline Schema_word cut_and_paste(const Schema_word& w, const Cut_and_paste_move& move) {
  const std::size_t n = w.size();
  Schema_word one, two;
  for (std::size_t i = move.from; i < move.to; ++i)
    one.push_back(w[i % n]);
  one.push_back({move.letter, true});
  for (std::size_t i = move.to; i < move.from + n; ++i)
    two.push_back(w[i % n]);
  two.push_back({move.letter, false});
  const auto at = [&](const Schema_word& piece) {
    return std::size_t(std::find_if(piece.begin(), piece.end(),
                                    [&](const Signed_letter& s) { return s.letter == move.glue; }) -
                       piece.begin());
  };
  const std::size_t i = at(one), j = at(two);
  Schema_word out;
  for (std::size_t k = j + 1; k < j + two.size(); ++k) // B': piece 2 after g^-1, up to it
    out.push_back(two[k % two.size()]);
  for (std::size_t k = i + 1; k < i + one.size(); ++k) // A': piece 1 after g, up to it
    out.push_back(one[k % one.size()]);
  return out;
}

/// The positions of `letter` in `w` (two for a paired side, one for a border side).
inline std::vector<std::size_t> positions(const Schema_word& w, std::size_t letter) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < w.size(); ++i)
    if (w[i].letter == letter)
      out.push_back(i);
  return out;
}

/// True when the commutator u v u^-1 v^-1 (any signs) starts at position i of the cyclic word.
inline bool commutator_at(const Schema_word& w, std::size_t i) {
  const std::size_t n = w.size();
  if (n < 4)
    return false;
  const Signed_letter& a = w[i % n];
  const Signed_letter& b = w[(i + 1) % n];
  const Signed_letter& c = w[(i + 2) % n];
  const Signed_letter& d = w[(i + 3) % n];
  return a.letter != b.letter && c.letter == a.letter && c.inverse != a.inverse &&
         d.letter == b.letter && d.inverse != b.inverse;
}

/// The moves that make a word canonical, and the word they give.
struct Canonical_plan {
  std::vector<Cut_and_paste_move> moves;
  Schema_word word;
  /// Where the final word's first commutator starts (0 when there is none).
  std::size_t first_commutator = 0;
  /// Commutators in the final word: the genus, when the plan succeeded.
  std::size_t commutators = 0;
};

/// Plans the cut-and-paste normalization of `w` (new diagonals get ids from `next_letter` on).
/// Each step takes two paired letters x, y that are linked (their occurrences alternate,
/// x .. y .. x^-1 .. y^-1 up to signs) and not yet in a commutator, and with two moves
/// (w = x A y B x^-1 C y^-1 D: cut from the corner before x to the one after x^-1 and glue along
/// y, giving D c C B x^-1 c^-1 x A — read from x^-1 when C and D are empty, so that no diagonal
/// runs along a single side; cut from the corner before c to the one before c^-1 and glue
/// along x) makes the contiguous commutator d c^-1 d^-1 c, leaving the blocks A..D whole, so
/// earlier commutators stay whole. Pairs already contiguous as a commutator take no move. On a
/// closed orientable one-vertex schema every paired letter is linked with another, so the plan
/// ends with the canonical word (2 moves per handle at most); paired letters that are not linked
/// (the sides that join a border to the rest, as in c h c^-1) are left as they are; the
/// commutators are then gathered into one run before them (three moves per block in between).
inline Canonical_plan plan_canonical_schema(Schema_word w, std::size_t next_letter) {
  Canonical_plan plan;
  std::vector<char> done;
  const auto is_done = [&](std::size_t l) { return l < done.size() && done[l]; };
  const auto set_done = [&](std::size_t l) {
    if (done.size() <= l)
      done.resize(l + 1, 0);
    done[l] = 1;
  };
  // The positions of letter l forwards and of l^-1 in v, the second one past the first by
  // `extra` more (read cyclically): the corners a move from before l to before (or after) l^-1
  // cuts between.
  const auto forwards_from = [](const Schema_word& v, std::size_t l, std::size_t extra) {
    const auto p = positions(v, l);
    const std::size_t f = v[p[0]].inverse ? p[1] : p[0], b = v[p[0]].inverse ? p[0] : p[1];
    return std::make_pair(f, b + extra < f ? b + extra + v.size() : b + extra);
  };
  for (;;) {
    const std::size_t n = w.size();
    // Commutators already contiguous.
    for (std::size_t i = 0; i < n; ++i)
      if (commutator_at(w, i) && !is_done(w[i].letter) && !is_done(w[(i + 1) % n].letter)) {
        set_done(w[i].letter);
        set_done(w[(i + 1) % n].letter);
      }
    // A linked pair (x, y) of free paired letters: y has one occurrence between x's two.
    bool found = false;
    std::size_t x = 0, y = 0;
    for (std::size_t i = 0; i < n && !found; ++i) {
      if (is_done(w[i].letter))
        continue;
      const auto px = positions(w, w[i].letter);
      if (px.size() != 2 || px[0] != i)
        continue;
      std::vector<std::size_t> inside;
      for (std::size_t k = px[0] + 1; k < px[1]; ++k)
        inside.push_back(w[k].letter);
      std::sort(inside.begin(), inside.end());
      for (std::size_t k = 0; k < inside.size() && !found; ++k) {
        const bool once = (k == 0 || inside[k - 1] != inside[k]) &&
                          (k + 1 == inside.size() || inside[k + 1] != inside[k]);
        if (once && !is_done(inside[k]) && positions(w, inside[k]).size() == 2) {
          found = true;
          x = w[i].letter;
          y = inside[k];
        }
      }
    }
    if (!found)
      break;
    // From the corner before x to the one after x^-1; when that leaves only y^-1 outside (C and D
    // empty: the diagonal would run along that one side), read the word from x^-1 instead.
    const auto px = positions(w, x);
    const Cut_and_paste_move first = px[1] - px[0] + 3 <= n
                                         ? Cut_and_paste_move{px[0], px[1] + 1, y, next_letter}
                                         : Cut_and_paste_move{px[1], px[0] + 1 + n, y, next_letter};
    ++next_letter;
    w = cut_and_paste(w, first);
    plan.moves.push_back(first);
    // Cut from before c to before c^-1.
    const auto [from, to] = forwards_from(w, first.letter, 0);
    const Cut_and_paste_move second{from, to, x, next_letter++};
    w = cut_and_paste(w, second);
    plan.moves.push_back(second);
    set_done(first.letter);
    set_done(second.letter);
  }
  // Gather the commutators (a bordered word has other blocks between them): with K the run of
  // commutators before a block H and C the commutator after it, K H C R becomes K C' H R in three
  // moves: cut from before H to after C's first letter x, glue along x (y^-1 R K c y c^-1 H); cut
  // from before c to after c^-1, glue along y (R K d H c^-1 d^-1 c); cut from before d to before
  // d^-1, glue along c (R K e d^-1 e^-1 d H).
  // K is the run that holds the first commutator (its letters are never moved), so it grows by
  // one commutator per three moves.
  std::size_t anchor = std::size_t(-1);
  for (std::size_t i = 0; i < w.size() && anchor == std::size_t(-1); ++i)
    if (commutator_at(w, i) && is_done(w[i].letter))
      anchor = w[i].letter;
  while (anchor != std::size_t(-1)) {
    const std::size_t n = w.size();
    std::vector<char> in_commutator(n, 0);
    std::size_t run = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (commutator_at(w, i) && is_done(w[i].letter)) {
        for (std::size_t k = 0; k < 4; ++k)
          in_commutator[(i + k) % n] = 1;
        if (w[i].letter == anchor)
          run = i;
      }
    std::size_t h = run; // H = w[h, c): the block after K
    while (h < run + n && in_commutator[h % n])
      h += 4;
    std::size_t c = h;
    while (c < run + n && !in_commutator[c % n])
      ++c;
    if (c >= run + n)
      break; // one run: gathered
    const std::size_t x = w[c % n].letter, y = w[(c + 1) % n].letter;
    const Cut_and_paste_move one{h % n, h % n + (c + 1 - h), x, next_letter++};
    w = cut_and_paste(w, one);
    const auto [c_from, c_to] = forwards_from(w, one.letter, 1);
    const Cut_and_paste_move two{c_from, c_to, y, next_letter++};
    w = cut_and_paste(w, two);
    const auto [d_from, d_to] = forwards_from(w, two.letter, 0);
    const Cut_and_paste_move three{d_from, d_to, one.letter, next_letter++};
    w = cut_and_paste(w, three);
    plan.moves.insert(plan.moves.end(), {one, two, three});
    set_done(two.letter);
    set_done(three.letter);
  }
  plan.word = w;
  // The first commutator: the start of the run (any commutator when they are all there is).
  const std::size_t n = w.size();
  const auto starts_commutator = [&](std::size_t i) {
    return commutator_at(w, i % n) && is_done(w[i % n].letter);
  };
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!starts_commutator(i))
      continue;
    if (!any)
      plan.first_commutator = i;
    any = true;
    if (!starts_commutator(i + n - 4)) {
      plan.first_commutator = i;
      break;
    }
  }
  for (std::size_t k = 0; k < w.size(); ++k) {
    const std::size_t i = (plan.first_commutator + k) % w.size();
    if (commutator_at(w, i) && is_done(w[i].letter)) {
      ++plan.commutators;
      k += 3;
    }
  }
  return plan;
}

/// The word as text, sides labelled by pairs in order of first appearance from position `start`:
/// a1 b1 a2 b2 … for the pairs, x^-1 for a side read backwards relative to its pair's first side,
/// B for a side with no partner. A canonical word reads "a1 b1 a1^-1 b1^-1 a2 b2 …".
inline std::string word_text(const Schema_word& w, std::size_t start = 0) {
  std::vector<std::size_t> label;
  std::vector<bool> first_inverse;
  std::vector<std::size_t> count;
  for (const Signed_letter& s : w) {
    if (count.size() <= s.letter)
      count.resize(s.letter + 1, 0);
    ++count[s.letter];
  }
  label.assign(count.size(), std::size_t(-1));
  first_inverse.assign(count.size(), false);
  std::size_t labels = 0;
  std::string out;
  for (std::size_t k = 0; k < w.size(); ++k) {
    const Signed_letter& s = w[(start + k) % w.size()];
    std::string t;
    if (count[s.letter] < 2)
      t = "B";
    else {
      const bool seen = label[s.letter] != std::size_t(-1);
      if (!seen) {
        label[s.letter] = labels++;
        first_inverse[s.letter] = s.inverse;
      }
      const std::size_t l = label[s.letter];
      t = std::string(l % 2 == 0 ? "a" : "b") + std::to_string(l / 2 + 1) +
          (s.inverse != first_inverse[s.letter] ? "^-1" : "");
    }
    out += (out.empty() ? "" : " ") + t;
  }
  return out;
}

} // namespace internal
} // namespace tessera
