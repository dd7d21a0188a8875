#pragma once
// Civil time for sun studies (issue 19): ISO 8601 date-times with a UTC offset, dates,
// step lengths ("10min", "1h30min"), the text written back in the CSV's time column,
// and the step instants of `penumbra sun` and `penumbra sun-hours`. docs/sun.md,
// "Time formats".
//
// Instants are UTC on the POSIX time line: every day has 86 400 s, so a leap second
// (23:59:60) cannot be written and is refused. The Sun moves 15 arcseconds in a
// second, so nothing here needs it. Resolution is one microsecond. Dates are in the
// proleptic Gregorian calendar, years 1 to 9999.

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::sun {

// A length of time; steps and offsets from the epoch are whole microseconds.
using Duration = std::chrono::microseconds;

// A UTC instant: the time since 1970-01-01T00:00:00Z, 86 400 s per day (POSIX time).
struct UtcInstant {
  Duration since_epoch{0};
};

inline bool operator==(UtcInstant a, UtcInstant b) {
  return a.since_epoch == b.since_epoch;
}
inline bool operator!=(UtcInstant a, UtcInstant b) {
  return !(a == b);
}
inline bool operator<(UtcInstant a, UtcInstant b) {
  return a.since_epoch < b.since_epoch;
}
inline bool operator<=(UtcInstant a, UtcInstant b) {
  return !(b < a);
}
inline bool operator>(UtcInstant a, UtcInstant b) {
  return b < a;
}
inline bool operator>=(UtcInstant a, UtcInstant b) {
  return !(a < b);
}
inline UtcInstant operator+(UtcInstant t, Duration d) {
  return UtcInstant{t.since_epoch + d};
}
inline UtcInstant operator-(UtcInstant t, Duration d) {
  return UtcInstant{t.since_epoch - d};
}
inline Duration operator-(UtcInstant a, UtcInstant b) {
  return a.since_epoch - b.since_epoch;
}

// A day of the proleptic Gregorian calendar.
struct CivilDate {
  int year = 1970;
  int month = 1;  // 1..12
  int day = 1;    // 1..days_in_month(year, month)
};

inline bool operator==(const CivilDate& a, const CivilDate& b) {
  return a.year == b.year && a.month == b.month && a.day == b.day;
}
inline bool operator!=(const CivilDate& a, const CivilDate& b) {
  return !(a == b);
}

// A date and a time of day as read on a clock (in some offset from UTC).
struct CivilDateTime {
  CivilDate date;
  int hour = 0;         // 0..23
  int minute = 0;       // 0..59
  int second = 0;       // 0..59
  int microsecond = 0;  // 0..999999
};

// An instant with the UTC offset it was written in (and is to be written back in).
struct ZonedInstant {
  UtcInstant utc;
  int offset_minutes = 0;  // local time minus UTC, within +-14 h
};

// Where a text comes from, so that errors can name it (like photometry::SpecContext):
// the scene file and JSON path ("lights[2].sun.time"), or "" and the option ("--from").
struct TextOrigin {
  std::string file;
  std::string location;
};

inline constexpr int kMaxOffsetMinutes = 14 * 60;

// returns whether year is a leap year of the Gregorian calendar.
bool is_leap_year(int year);

// returns the number of days of month (1..12) in year.
int days_in_month(int year, int month);

// returns the number of days from 1970-01-01 to date (negative before it).
std::int64_t days_since_epoch(const CivilDate& date);

// returns the date days after 1970-01-01; the inverse of days_since_epoch.
CivilDate date_from_days(std::int64_t days);

// returns the UTC instant at which a clock offset_minutes ahead of UTC reads local.
UtcInstant utc_instant(const CivilDateTime& local, int offset_minutes);

// returns what a clock offset_minutes ahead of UTC reads at instant t.
CivilDateTime civil_date_time(UtcInstant t, int offset_minutes);

// returns the instant at which the local date begins (00:00 on a clock offset_minutes
// ahead of UTC).
UtcInstant local_midnight(const CivilDate& date, int offset_minutes);

// parses an ISO 8601 date-time, YYYY-MM-DDThh:mm[:ss[.ffffff]] followed by an offset
// Z, +hh:mm, -hh:mm, +hhmm or +hh. Text without an offset takes default_offset_minutes;
// when that is empty such text is refused. Throws InputError(origin.file,
// origin.location, what is wrong) for malformed text and for values out of range.
ZonedInstant parse_date_time(std::string_view text, std::optional<int> default_offset_minutes,
                             const TextOrigin& origin = {});

// parses an ISO 8601 calendar date YYYY-MM-DD; throws InputError like parse_date_time.
CivilDate parse_date(std::string_view text, const TextOrigin& origin = {});

// parses a step length: whole numbers with units h, min and s, largest unit first and
// each at most once ("10min", "1h", "30s", "1h30min", "2h15min30s"). The result is
// positive; throws InputError like parse_date_time.
Duration parse_step(std::string_view text, const TextOrigin& origin = {});

// returns t as ISO 8601 text on a clock offset_minutes ahead of UTC, with the offset
// written +hh:mm (UTC is "+00:00"): "2026-03-21T12:00:00+00:00". Fractional seconds
// appear only when t has them, without trailing zeros. parse_date_time reads the text
// back to t.
std::string format_date_time(UtcInstant t, int offset_minutes);

// returns the instants from from.utc to to (both inclusive) that lie a whole number of
// steps after local midnight of from's date, local meaning from.offset_minutes (DESIGN.md:
// "steps fall on whole multiples of --step from local midnight"). The count continues
// across days from that one midnight, so a step that does not divide 24 h drifts against
// later midnights. Empty when to < from.utc; at most (to - from.utc) / step + 1 instants,
// which callers taking a range from the user should bound first. Throws
// std::invalid_argument when step is not positive.
std::vector<UtcInstant> step_instants(const ZonedInstant& from, UtcInstant to, Duration step);

}  // namespace penumbra::sun
