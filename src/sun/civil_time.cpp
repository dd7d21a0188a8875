#include "penumbra/sun/civil_time.h"

#include <erfa.h>
#include <erfam.h>

#include <cstdio>
#include <stdexcept>

#include "penumbra/base/input_error.h"

namespace penumbra::sun {
namespace {

constexpr std::int64_t kMicrosecondsPerDay = 86'400'000'000;
// The Modified Julian Date of 1970-01-01, the POSIX epoch.
constexpr std::int64_t kEpochMjd = 40'587;

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

bool valid_date(const CivilDate& date) {
  return date.year >= 1 && date.year <= 9999 && date.month >= 1 && date.month <= 12 &&
         date.day >= 1 && date.day <= days_in_month(date.year, date.month);
}

std::string quoted(std::string_view text) {
  return "\"" + std::string(text) + "\"";
}

std::string two_digits(int value) {
  char text[8];
  std::snprintf(text, sizeof text, "%02d", value);
  return text;
}

const char* const kMonthNames[] = {"January",   "February", "March",    "April",
                                   "May",       "June",     "July",     "August",
                                   "September", "October",  "November", "December"};

// Reads the fixed-width fields of an ISO 8601 text left to right; every failure names
// the whole text and what was expected.
class IsoReader {
 public:
  IsoReader(std::string_view text, const TextOrigin& origin, const char* form)
      : text_(text), origin_(origin), form_(form) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(origin_.file, origin_.location, message);
  }
  [[noreturn]] void malformed(const std::string& what) const {
    fail("not an ISO 8601 " + std::string(form_) + ": " + quoted(text_) + " (" + what + ")");
  }

  bool at_end() const { return next_ == text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[next_]; }

  // reads exactly width decimal digits.
  int digits(int width, const char* name) {
    int value = 0;
    for (int i = 0; i < width; ++i, ++next_) {
      if (at_end() || peek() < '0' || peek() > '9')
        malformed("expected " + std::to_string(width) + " digits for the " + name);
      value = 10 * value + (peek() - '0');
    }
    return value;
  }

  void expect(char separator, const char* where) {
    if (peek() != separator) malformed(std::string("expected '") + separator + "' " + where);
    ++next_;
  }

  bool accept(char c) {
    if (peek() != c) return false;
    ++next_;
    return true;
  }

  CivilDate date() {
    CivilDate date;
    date.year = digits(4, "year");
    expect('-', "after the year");
    date.month = digits(2, "month");
    expect('-', "after the month");
    date.day = digits(2, "day");
    if (date.year < 1) fail("year 0000 is outside 0001..9999 in " + quoted(text_));
    if (date.month < 1 || date.month > 12)
      fail("month " + two_digits(date.month) + " is not in 01..12 in " + quoted(text_));
    const int days = days_in_month(date.year, date.month);
    if (date.day < 1 || date.day > days)
      fail("day " + two_digits(date.day) + " is not in " + kMonthNames[date.month - 1] + " " +
           std::to_string(date.year) + " (" + std::to_string(days) + " days) in " + quoted(text_));
    return date;
  }

  // reads hh:mm[:ss[.ffffff]].
  void time_of_day(CivilDateTime& time) {
    time.hour = digits(2, "hour");
    expect(':', "after the hour");
    time.minute = digits(2, "minute");
    if (accept(':')) {
      time.second = digits(2, "second");
      if (accept('.') || accept(',')) {
        int count = 0;
        int fraction = 0;
        while (!at_end() && peek() >= '0' && peek() <= '9') {
          if (++count > 6) malformed("at most 6 digits of a second (microseconds)");
          fraction = 10 * fraction + (text_[next_++] - '0');
        }
        if (count == 0) malformed("expected digits after the decimal sign");
        for (; count < 6; ++count) fraction *= 10;
        time.microsecond = fraction;
      }
    }
    if (time.hour > 23)
      fail("hour " + two_digits(time.hour) + " is not in 00..23 in " + quoted(text_));
    if (time.minute > 59)
      fail("minute " + two_digits(time.minute) + " is not in 00..59 in " + quoted(text_));
    if (time.second == 60) fail("leap seconds (second 60) are not supported in " + quoted(text_));
    if (time.second > 59)
      fail("second " + two_digits(time.second) + " is not in 00..59 in " + quoted(text_));
  }

  // reads Z, +hh:mm, +hhmm or +hh (or '-'); empty at the end of the text.
  std::optional<int> offset() {
    if (at_end()) return std::nullopt;
    if (accept('Z') || accept('z')) return 0;
    const char sign = peek();
    if (sign != '+' && sign != '-')
      malformed("expected the end or a UTC offset such as Z, +01:00 or -05:30");
    ++next_;
    const int hours = digits(2, "offset hours");
    int minutes = 0;
    if (accept(':'))
      minutes = digits(2, "offset minutes");
    else if (!at_end())
      minutes = digits(2, "offset minutes");
    if (minutes > 59)
      fail("offset minutes " + two_digits(minutes) + " are not in 00..59 in " + quoted(text_));
    const int total = 60 * hours + minutes;
    if (total > kMaxOffsetMinutes)
      fail("offset " + std::string(1, sign) + two_digits(hours) + ":" + two_digits(minutes) +
           " is beyond +-14:00 in " + quoted(text_));
    return sign == '-' ? -total : total;
  }

  void finish() {
    if (!at_end()) malformed("unexpected " + quoted(text_.substr(next_)) + " at the end");
  }

 private:
  std::string_view text_;
  const TextOrigin& origin_;
  const char* form_;
  std::size_t next_ = 0;
};

// Throws the InputError of a malformed step length.
struct StepError {
  std::string_view text;
  const TextOrigin& origin;

  [[noreturn]] void operator()(const std::string& message) const {
    throw InputError(origin.file, origin.location,
                     "not a step length: " + quoted(text) + " (" + message + ")");
  }
};

}  // namespace

bool is_leap_year(int year) {
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

int days_in_month(int year, int month) {
  static const int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12) throw std::invalid_argument("days_in_month: month not in 1..12");
  return month == 2 && is_leap_year(year) ? 29 : kDays[month - 1];
}

std::int64_t days_since_epoch(const CivilDate& date) {
  if (!valid_date(date)) throw std::invalid_argument("days_since_epoch: not a valid date");
  // ERFA's eraCal2jd counts Gregorian days exactly (integer arithmetic inside).
  double mjd_zero = 0, mjd = 0;
  eraCal2jd(date.year, date.month, date.day, &mjd_zero, &mjd);
  return static_cast<std::int64_t>(mjd) - kEpochMjd;
}

CivilDate date_from_days(std::int64_t days) {
  // eraJd2cal with the MJD split keeps both parts exact: 2400000.5 + an integer MJD.
  int year = 0, month = 0, day = 0;
  double fraction = 0;
  if (eraJd2cal(ERFA_DJM0, static_cast<double>(days + kEpochMjd), &year, &month, &day, &fraction) !=
      0)
    throw std::invalid_argument("date_from_days: outside the calendar ERFA supports");
  return {year, month, day};
}

UtcInstant utc_instant(const CivilDateTime& local, int offset_minutes) {
  if (!valid_date(local.date) || local.hour < 0 || local.hour > 23 || local.minute < 0 ||
      local.minute > 59 || local.second < 0 || local.second > 59 || local.microsecond < 0 ||
      local.microsecond > 999'999)
    throw std::invalid_argument("utc_instant: not a valid date and time of day");
  const std::int64_t seconds_of_day =
      3600 * std::int64_t{local.hour} + 60 * local.minute + local.second - 60 * offset_minutes;
  return UtcInstant{Duration{days_since_epoch(local.date) * kMicrosecondsPerDay +
                             seconds_of_day * 1'000'000 + local.microsecond}};
}

CivilDateTime civil_date_time(UtcInstant t, int offset_minutes) {
  const std::int64_t local = t.since_epoch.count() + std::int64_t{offset_minutes} * 60'000'000;
  const std::int64_t days = floor_div(local, kMicrosecondsPerDay);
  std::int64_t rest = local - days * kMicrosecondsPerDay;
  CivilDateTime result;
  result.date = date_from_days(days);
  result.hour = static_cast<int>(rest / 3'600'000'000);
  rest %= 3'600'000'000;
  result.minute = static_cast<int>(rest / 60'000'000);
  rest %= 60'000'000;
  result.second = static_cast<int>(rest / 1'000'000);
  result.microsecond = static_cast<int>(rest % 1'000'000);
  return result;
}

UtcInstant local_midnight(const CivilDate& date, int offset_minutes) {
  CivilDateTime midnight;
  midnight.date = date;
  return utc_instant(midnight, offset_minutes);
}

ZonedInstant parse_date_time(std::string_view text, std::optional<int> default_offset_minutes,
                             const TextOrigin& origin) {
  IsoReader in(text, origin, "date-time");
  CivilDateTime local;
  local.date = in.date();
  if (!in.accept('T') && !in.accept('t'))
    in.malformed("expected 'T' between the date and the time, as in 2026-03-21T12:00:00+00:00");
  in.time_of_day(local);
  std::optional<int> offset = in.offset();
  in.finish();
  if (!offset) {
    if (!default_offset_minutes)
      in.fail(quoted(text) +
              " has no UTC offset: add Z or +hh:mm, as in 2026-03-21T12:00:00+00:00");
    offset = default_offset_minutes;
  }
  return {utc_instant(local, *offset), *offset};
}

CivilDate parse_date(std::string_view text, const TextOrigin& origin) {
  IsoReader in(text, origin, "date");
  const CivilDate date = in.date();
  if (!in.at_end()) in.malformed("expected YYYY-MM-DD only");
  return date;
}

Duration parse_step(std::string_view text, const TextOrigin& origin) {
  const StepError fail{text, origin};
  static const struct {
    const char* name;
    std::int64_t microseconds;
  } kUnits[] = {{"h", 3'600'000'000}, {"min", 60'000'000}, {"s", 1'000'000}};
  if (text.empty()) fail("expected a number and a unit h, min or s, as in 10min or 1h30min");
  std::int64_t total = 0;
  std::size_t next = 0;
  int smallest_used = -1;  // index in kUnits of the last unit read
  while (next < text.size()) {
    std::int64_t value = 0;
    std::size_t digits = 0;
    while (next < text.size() && text[next] >= '0' && text[next] <= '9') {
      if (++digits > 9) fail("a number has more than 9 digits");
      value = 10 * value + (text[next++] - '0');
    }
    if (digits == 0) fail("expected a whole number before each unit, as in 10min or 1h30min");
    std::size_t unit_end = next;
    while (unit_end < text.size() && (text[unit_end] < '0' || text[unit_end] > '9')) ++unit_end;
    const std::string_view unit = text.substr(next, unit_end - next);
    int index = -1;
    for (int i = 0; i < 3; ++i)
      if (unit == kUnits[i].name) index = i;
    if (index < 0) {
      if (unit.empty()) fail("the number " + std::to_string(value) + " has no unit h, min or s");
      if (unit == "m") fail("unit \"m\" is ambiguous: write \"min\" for minutes");
      fail("unknown unit " + quoted(unit) + ": use h, min or s");
    }
    if (index <= smallest_used)
      fail("units must come largest first (h, min, s), each at most once");
    smallest_used = index;
    total += value * kUnits[index].microseconds;
    next = unit_end;
  }
  if (total <= 0) fail("a step must be longer than zero");
  return Duration{total};
}

std::string format_date_time(UtcInstant t, int offset_minutes) {
  if (offset_minutes < -kMaxOffsetMinutes || offset_minutes > kMaxOffsetMinutes)
    throw std::invalid_argument("format_date_time: offset beyond +-14 h");
  const CivilDateTime local = civil_date_time(t, offset_minutes);
  char text[64];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d", local.date.year,
                local.date.month, local.date.day, local.hour, local.minute, local.second);
  std::string result = text;
  if (local.microsecond != 0) {
    std::snprintf(text, sizeof text, ".%06d", local.microsecond);
    std::string fraction = text;
    while (fraction.back() == '0') fraction.pop_back();
    result += fraction;
  }
  const int magnitude = offset_minutes < 0 ? -offset_minutes : offset_minutes;
  std::snprintf(text, sizeof text, "%c%02d:%02d", offset_minutes < 0 ? '-' : '+', magnitude / 60,
                magnitude % 60);
  return result + text;
}

std::vector<UtcInstant> step_instants(const ZonedInstant& from, UtcInstant to, Duration step) {
  if (step.count() <= 0) throw std::invalid_argument("step_instants: the step must be positive");
  std::vector<UtcInstant> instants;
  if (to < from.utc) return instants;
  const UtcInstant origin =
      local_midnight(civil_date_time(from.utc, from.offset_minutes).date, from.offset_minutes);
  // from.utc >= origin, so both counts are non-negative: first = ceil, last = floor.
  const std::int64_t first = ((from.utc - origin) + step - Duration{1}) / step;
  const std::int64_t last = (to - origin) / step;
  for (std::int64_t k = first; k <= last; ++k) instants.push_back(origin + k * step);
  return instants;
}

}  // namespace penumbra::sun
