#include "engine/analysis/Statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <immintrin.h>

#include "engine/analysis/CpuLanes.h"

namespace hemiroll::analysis {

double mean(std::span<const double> values) {
  if (values.empty()) return 0.0;
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

namespace {

// The values a sort would put at ranks `below` and `above` (below or
// below + 1).
struct Ranked {
  double low = 0.0, high = 0.0;
};

// By selection over a copy of them all: nth_element puts the one below in
// place, and the one above is the smallest of what lies after it.
Ranked selectOverAll(std::span<const double> values, std::size_t below, std::size_t above) {
  std::vector<double> work(values.begin(), values.end());
  std::nth_element(work.begin(), work.begin() + static_cast<std::ptrdiff_t>(below), work.end());
  const double low = work[below];
  const double high = above == below ? low : *std::min_element(work.begin() + static_cast<std::ptrdiff_t>(above), work.end());
  return {low, high};
}

// Copies the values within [lo, hi] to `kept` (room for n + 8) and counts
// those below lo and above hi, eight at a time by AVX-512's compress; NaNs
// are in no count. Returns how many were kept.
__attribute__((target("avx512f"))) std::size_t keepWithin(const double* v, std::size_t n, double lo, double hi,
                                                           double* kept, std::size_t& less, std::size_t& more) {
  const __m512d low = _mm512_set1_pd(lo), high = _mm512_set1_pd(hi);
  std::size_t k = 0, i = 0;
  less = more = 0;
  for (; i + 8 <= n; i += 8) {
    const __m512d x = _mm512_loadu_pd(v + i);
    const __mmask8 under = _mm512_cmp_pd_mask(x, low, _CMP_LT_OQ), over = _mm512_cmp_pd_mask(x, high, _CMP_GT_OQ);
    const __mmask8 inside = _mm512_cmp_pd_mask(x, low, _CMP_GE_OQ) & _mm512_cmp_pd_mask(x, high, _CMP_LE_OQ);
    _mm512_storeu_pd(kept + k, _mm512_maskz_compress_pd(inside, x));
    k += static_cast<std::size_t>(__builtin_popcount(inside));
    less += static_cast<std::size_t>(__builtin_popcount(under));
    more += static_cast<std::size_t>(__builtin_popcount(over));
  }
  for (; i < n; ++i) {
    if (v[i] < lo) ++less;
    else if (v[i] > hi) ++more;
    else if (v[i] >= lo && v[i] <= hi) kept[k++] = v[i];
  }
  return k;
}

// Floyd and Rivest's idea (issue 32: nth_element over whole columns had
// been ~10 % of a sweep point's analysis): the order statistics of a sample
// of 256 bracket the wanted ranks, one pass keeps what lies within the
// bracket (about a sixth) and counts what lies below it, and the selection
// runs on what was kept. The kept values are exactly ranks [less, less +
// kept) of the whole, so the values found are the sort's. Where the bracket
// misses the ranks (or a value is NaN), the selection runs over all.
bool selectsByBracket(std::size_t n) {
  return widestDoubleLanes() == 8 && n >= 2048;  // below, a sort of the sample is no longer small beside the selection
}

constexpr std::size_t kSample = 256;

// The sample the brackets come from, sorted; false where one of it is NaN.
bool sortedSample(std::span<const double> values, double (&sample)[kSample]) {
  const std::size_t stride = values.size() / kSample;
  for (std::size_t j = 0; j < kSample; ++j) {
    sample[j] = values[j * stride + stride / 2];
    if (std::isnan(sample[j])) return false;
  }
  std::sort(sample, sample + kSample);
  return true;
}

// By the bracket the sorted sample gives ranks below and above.
Ranked selectRanksBracketed(std::span<const double> values, std::size_t below, std::size_t above,
                            const double (&sample)[kSample]) {
  constexpr std::size_t kMargin = 20;
  const std::size_t n = values.size();
  const auto at = static_cast<std::size_t>((static_cast<double>(below) + 0.5) / static_cast<double>(n) * kSample);
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const double lo = at < kMargin ? -kInfinity : sample[at - kMargin];
  const double hi = at + 1 + kMargin >= kSample ? kInfinity : sample[at + 1 + kMargin];
  thread_local std::vector<double> kept;
  kept.resize(n + 8);
  std::size_t less = 0, more = 0;
  const std::size_t k = keepWithin(values.data(), n, lo, hi, kept.data(), less, more);
  if (less + k + more != n || below < less || above >= less + k) return selectOverAll(values, below, above);
  double* first = kept.data();
  std::nth_element(first, first + (below - less), first + k);
  const double low = first[below - less];
  const double high = above == below ? low : *std::min_element(first + (above - less), first + k);
  return {low, high};
}

Ranked selectRanks(std::span<const double> values, std::size_t below, std::size_t above) {
  double sample[kSample];
  if (!selectsByBracket(values.size()) || !sortedSample(values, sample)) return selectOverAll(values, below, above);
  return selectRanksBracketed(values, below, above, sample);
}

// quantile's two ranks and the weight between them, for q.
struct QuantileRanks {
  std::size_t below, above;
  double w;
};
QuantileRanks ranksOf(std::size_t n, double q) {
  const double at = std::clamp(q, 0.0, 1.0) * static_cast<double>(n - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  return {below, std::min(below + 1, n - 1), at - static_cast<double>(below)};
}

}  // namespace

// The two order statistics by selection, not by sorting (issue 32: the
// sort was 6-9 % of a sweep point): the same two values as a sort's, so
// the same result to the bit.
double quantile(std::span<const double> values, double q) {
  if (values.empty()) return 0.0;
  const QuantileRanks at = ranksOf(values.size(), q);
  const Ranked r = selectRanks(values, at.below, at.above);
  return r.low * (1.0 - at.w) + r.high * at.w;
}

// From the highest rank down: after the selection of rank b within [0, end),
// [0, b) holds what lies below it and (b, end) what lies above, and
// everything from `end` on is at least work[end] (the previous rank's
// value), so the value at rank b + 1 is the least of (b, end] (the sort's).
std::vector<double> quantiles(std::span<const double> values, std::span<const double> qs) {
  std::vector<double> out(qs.size(), 0.0);
  if (values.empty()) return out;
  if (selectsByBracket(values.size())) {
    // One pass per q is then cheaper than the nesting below: quantile's,
    // but the sample is the same for every q, so it is sorted once (issue 32).
    double sample[kSample];
    const bool bracketed = sortedSample(values, sample);
    for (std::size_t i = 0; i < qs.size(); ++i) {
      const QuantileRanks at = ranksOf(values.size(), qs[i]);
      const Ranked r = bracketed ? selectRanksBracketed(values, at.below, at.above, sample)
                                 : selectOverAll(values, at.below, at.above);
      out[i] = r.low * (1.0 - at.w) + r.high * at.w;
    }
    return out;
  }
  std::vector<double> work(values.begin(), values.end());
  const std::size_t n = work.size();
  struct Rank {
    std::size_t q, below, above;
    double w;
  };
  std::vector<Rank> ranks;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    const double at = std::clamp(qs[i], 0.0, 1.0) * static_cast<double>(n - 1);
    const auto below = static_cast<std::size_t>(std::floor(at));
    ranks.push_back({i, below, std::min(below + 1, n - 1), at - static_cast<double>(below)});
  }
  std::sort(ranks.begin(), ranks.end(), [](const Rank& a, const Rank& b) { return a.below > b.below; });
  std::size_t end = n;
  double low = 0.0, high = 0.0;
  for (const Rank& r : ranks) {
    if (r.below < end) {
      const auto first = work.begin();
      std::nth_element(first, first + static_cast<std::ptrdiff_t>(r.below), first + static_cast<std::ptrdiff_t>(end));
      low = work[r.below];
      if (r.above == r.below) {
        high = low;
      } else {
        const std::size_t last = std::min(end, n - 1);  // (b, end], within the values
        high = *std::min_element(first + static_cast<std::ptrdiff_t>(r.above), first + static_cast<std::ptrdiff_t>(last) + 1);
      }
      end = r.below;
    }  // else: the same rank as the one before, whose low and high stand
    out[r.q] = low * (1.0 - r.w) + high * r.w;
  }
  return out;
}

double median(std::span<const double> values) { return quantile(values, 0.5); }

double standardDeviation(std::span<const double> values) {
  if (values.size() < 2) return 0.0;
  const double m = mean(values);
  double sum = 0.0;
  for (double v : values) sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

Estimate summarize(std::span<const double> values) {
  return {median(values), standardDeviation(values), static_cast<int>(values.size())};
}

}  // namespace hemiroll::analysis
