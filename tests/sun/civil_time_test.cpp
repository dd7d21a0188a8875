// Civil time: ISO 8601 date-times with offsets, dates, step lengths, the CSV's time
// text and the step instants. Expected instants are derived by hand in each case (day
// counts written out) or are well-known POSIX times.

#include <boost/test/unit_test.hpp>

#include <string>

#include "penumbra/base/input_error.h"
#include "penumbra/sun/civil_time.h"

using namespace penumbra::sun;
using penumbra::InputError;

namespace {

constexpr std::int64_t kSecond = 1'000'000;
constexpr std::int64_t kDay = 86'400 * kSecond;

UtcInstant utc(const std::string& text) {
  return parse_date_time(text, std::nullopt).utc;
}

std::int64_t seconds(UtcInstant t) {
  return t.since_epoch.count() / kSecond;
}

// checks that parsing text throws an InputError whose message contains fragment.
template <typename Parse>
void check_refused(Parse parse, const std::string& text, const std::string& fragment) {
  BOOST_TEST_CONTEXT(text) {
    try {
      parse(text);
      BOOST_ERROR("accepted \"" + text + "\"");
    } catch (const InputError& e) {
      BOOST_TEST_MESSAGE(e.what());
      BOOST_TEST(e.message().find(fragment) != std::string::npos, e.message());
    }
  }
}

void check_date_time_refused(const std::string& text, const std::string& fragment) {
  check_refused([](const std::string& t) { parse_date_time(t, 0); }, text, fragment);
}

void check_step_refused(const std::string& text, const std::string& fragment) {
  check_refused([](const std::string& t) { parse_step(t); }, text, fragment);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(civil_time)

// === The calendar

BOOST_AUTO_TEST_CASE(leap_years_follow_the_gregorian_rule) {
  BOOST_TEST(is_leap_year(2024));
  BOOST_TEST(!is_leap_year(2026));
  BOOST_TEST(!is_leap_year(1900));  // divisible by 100, not by 400
  BOOST_TEST(is_leap_year(2000));   // divisible by 400
  BOOST_TEST(days_in_month(2024, 2) == 29);
  BOOST_TEST(days_in_month(2026, 2) == 28);
  BOOST_TEST(days_in_month(2026, 4) == 30);
  BOOST_TEST(days_in_month(2026, 12) == 31);
}

BOOST_AUTO_TEST_CASE(day_numbers_count_every_day_of_four_centuries) {
  // A second method: walk the calendar day by day with days_in_month from 1900-01-01
  // (25567 days before the epoch: 70 years with 17 leap days, 1904..1968) to 2300.
  CivilDate date{1900, 1, 1};
  std::int64_t days = -(70 * 365 + 17);
  while (date.year < 2300) {
    BOOST_TEST_REQUIRE(days_since_epoch(date) == days);
    const CivilDate back = date_from_days(days);
    BOOST_TEST_REQUIRE((back == date));
    ++days;
    if (++date.day > days_in_month(date.year, date.month)) {
      date.day = 1;
      if (++date.month > 12) {
        date.month = 1;
        ++date.year;
      }
    }
  }
  // The ends of the supported range round-trip too.
  BOOST_TEST((date_from_days(days_since_epoch({1, 1, 1})) == CivilDate{1, 1, 1}));
  BOOST_TEST((date_from_days(days_since_epoch({9999, 12, 31})) == CivilDate{9999, 12, 31}));
}

// === Date-times

BOOST_AUTO_TEST_CASE(utc_date_times_match_well_known_posix_times) {
  BOOST_TEST(seconds(utc("1970-01-01T00:00:00Z")) == 0);
  BOOST_TEST(seconds(utc("2000-01-01T00:00:00+00:00")) == 946'684'800);
  BOOST_TEST(seconds(utc("2038-01-19T03:14:07Z")) == 2'147'483'647);  // 2^31 - 1
  BOOST_TEST(seconds(utc("1969-12-31T23:59:59Z")) == -1);
  // 2026-03-21: 56 years after 1970 with 14 leap days (1972..2024), then 31 + 28 + 20
  // days: 20533 days; plus 12 h.
  BOOST_TEST(seconds(utc("2026-03-21T12:00:00+00:00")) == 20533 * 86400 + 43200);
}

BOOST_AUTO_TEST_CASE(offsets_name_the_same_instant) {
  const UtcInstant noon = utc("2026-03-21T12:00:00Z");
  BOOST_TEST((utc("2026-03-21T12:00:00+00:00") == noon));
  BOOST_TEST((utc("2026-03-21T17:30:00+05:30") == noon));
  BOOST_TEST((utc("2026-03-21T17:30:00+0530") == noon));
  BOOST_TEST((utc("2026-03-21T05:00:00-07:00") == noon));
  BOOST_TEST((utc("2026-03-21T05:00-07") == noon));  // minutes only, hour-only offset
  BOOST_TEST((utc("2026-03-22T02:00:00+14:00") == noon));
  BOOST_TEST((utc("2026-03-20T22:00:00-14:00") == noon));
  BOOST_TEST((utc("2026-03-21t12:00:00z") == noon));
  // The offset is kept for writing back.
  BOOST_TEST(parse_date_time("2026-03-21T17:30:00+05:30", std::nullopt).offset_minutes == 330);
  BOOST_TEST(parse_date_time("2026-03-21T05:00:00-07:00", std::nullopt).offset_minutes == -420);
}

BOOST_AUTO_TEST_CASE(text_without_an_offset_takes_the_default) {
  const ZonedInstant local = parse_date_time("2026-03-21T13:00:00", 60);
  BOOST_TEST(local.offset_minutes == 60);
  BOOST_TEST((local.utc == utc("2026-03-21T12:00:00Z")));
  // An explicit offset wins over the default.
  BOOST_TEST(parse_date_time("2026-03-21T13:00:00Z", 60).offset_minutes == 0);
  check_refused([](const std::string& t) { parse_date_time(t, std::nullopt); },
                "2026-03-21T13:00:00", "has no UTC offset");
}

BOOST_AUTO_TEST_CASE(fractional_seconds_are_microseconds) {
  const UtcInstant whole = utc("2026-03-21T12:00:30Z");
  BOOST_TEST((utc("2026-03-21T12:00:30.5Z") - whole).count() == 500'000);
  BOOST_TEST((utc("2026-03-21T12:00:30,25Z") - whole).count() == 250'000);  // ISO's comma
  BOOST_TEST((utc("2026-03-21T12:00:30.000001Z") - whole).count() == 1);
  BOOST_TEST((utc("2026-03-21T12:00:30.123456+01:00") - whole).count() == 123'456 - 3600 * kSecond);
  check_date_time_refused("2026-03-21T12:00:30.1234567Z", "at most 6 digits");
  check_date_time_refused("2026-03-21T12:00:30.Z", "digits after the decimal sign");
}

BOOST_AUTO_TEST_CASE(leap_days_exist_only_in_leap_years) {
  BOOST_TEST(seconds(utc("2024-03-01T00:00:00Z")) - seconds(utc("2024-02-29T00:00:00Z")) == 86400);
  BOOST_TEST(seconds(utc("2000-03-01T00:00:00Z")) - seconds(utc("2000-02-28T00:00:00Z")) ==
             2 * 86400);
  check_date_time_refused("2026-02-29T00:00:00Z", "day 29 is not in February 2026 (28 days)");
  check_date_time_refused("1900-02-29T00:00:00Z", "(28 days)");
  check_date_time_refused("2026-04-31T00:00:00Z", "day 31 is not in April 2026 (30 days)");
}

BOOST_AUTO_TEST_CASE(out_of_range_fields_are_refused_with_their_name) {
  check_date_time_refused("2026-13-01T00:00:00Z", "month 13 is not in 01..12");
  check_date_time_refused("2026-00-01T00:00:00Z", "month 00 is not in 01..12");
  check_date_time_refused("2026-01-00T00:00:00Z", "day 00 is not in January 2026");
  check_date_time_refused("2026-01-32T00:00:00Z", "day 32 is not in January 2026 (31 days)");
  check_date_time_refused("0000-01-01T00:00:00Z", "year 0000");
  check_date_time_refused("2026-01-01T24:00:00Z", "hour 24 is not in 00..23");
  check_date_time_refused("2026-01-01T12:60:00Z", "minute 60 is not in 00..59");
  check_date_time_refused("2016-12-31T23:59:60Z", "leap seconds");
  check_date_time_refused("2026-01-01T12:00:61Z", "second 61 is not in 00..59");
  check_date_time_refused("2026-01-01T12:00:00+14:01", "offset +14:01 is beyond +-14:00");
  check_date_time_refused("2026-01-01T12:00:00-15:00", "offset -15:00 is beyond +-14:00");
  check_date_time_refused("2026-01-01T12:00:00+05:60", "offset minutes 60");
}

BOOST_AUTO_TEST_CASE(malformed_text_is_refused_with_the_expected_form) {
  check_date_time_refused("", "expected 4 digits for the year");
  check_date_time_refused("2026-3-21T12:00:00Z", "expected 2 digits for the month");
  check_date_time_refused("2026/03/21T12:00:00Z", "expected '-' after the year");
  check_date_time_refused("2026-03-21 12:00:00Z", "expected 'T' between the date and the time");
  check_date_time_refused("2026-03-21", "expected 'T'");
  check_date_time_refused("2026-03-21T12Z", "expected ':' after the hour");
  check_date_time_refused("2026-03-21T12:00:00 +01:00", "expected the end or a UTC offset");
  check_date_time_refused("2026-03-21T12:00:00+1", "expected 2 digits for the offset hours");
  check_date_time_refused("2026-03-21T12:00:00Zulu", "unexpected \"ulu\" at the end");
  check_date_time_refused("2026-03-21T12:00:00+01:00:00", "unexpected \":00\" at the end");
}

BOOST_AUTO_TEST_CASE(errors_name_where_the_text_came_from) {
  try {
    parse_date_time("2026-13-01T00:00:00Z", std::nullopt, {"scene.json", "lights[2].sun.time"});
    BOOST_ERROR("accepted month 13");
  } catch (const InputError& e) {
    BOOST_TEST(e.file() == "scene.json");
    BOOST_TEST(e.location() == "lights[2].sun.time");
    BOOST_TEST(std::string(e.what()) ==
               "scene.json: lights[2].sun.time: month 13 is not in 01..12 in "
               "\"2026-13-01T00:00:00Z\"");
  }
  try {
    parse_step("10m", {"", "--step"});
    BOOST_ERROR("accepted 10m");
  } catch (const InputError& e) {
    BOOST_TEST(e.location() == "--step");
  }
}

// === Writing instants back

BOOST_AUTO_TEST_CASE(formatting_writes_the_offset_and_round_trips) {
  const UtcInstant noon = utc("2026-03-21T12:00:00Z");
  BOOST_TEST(format_date_time(noon, 0) == "2026-03-21T12:00:00+00:00");
  BOOST_TEST(format_date_time(noon, 330) == "2026-03-21T17:30:00+05:30");
  BOOST_TEST(format_date_time(noon, 345) == "2026-03-21T17:45:00+05:45");
  BOOST_TEST(format_date_time(noon, -420) == "2026-03-21T05:00:00-07:00");
  BOOST_TEST(format_date_time(noon, -30) == "2026-03-21T11:30:00-00:30");
  BOOST_TEST(format_date_time(noon, 14 * 60) == "2026-03-22T02:00:00+14:00");
  BOOST_TEST(format_date_time(noon + Duration{500'000}, 0) == "2026-03-21T12:00:00.5+00:00");
  BOOST_TEST(format_date_time(noon + Duration{1}, 0) == "2026-03-21T12:00:00.000001+00:00");
  BOOST_TEST(format_date_time(utc("1969-12-31T23:59:59.75Z"), 0) == "1969-12-31T23:59:59.75+00:00");
  // Text in canonical form comes back unchanged.
  for (const char* text :
       {"2026-03-21T12:00:00+00:00", "2024-02-29T23:59:59.999999-03:30",
        "1910-06-15T06:30:00+09:00", "0001-01-01T00:00:00+00:00", "9999-12-31T23:59:59+00:00"}) {
    const ZonedInstant parsed = parse_date_time(text, std::nullopt);
    BOOST_TEST(format_date_time(parsed.utc, parsed.offset_minutes) == text);
  }
  // Instants come back unchanged, across the epoch and with odd microseconds.
  for (std::int64_t t = -40 * 365 * kDay; t < 80 * 365 * kDay; t += 7 * kDay / 3 + 12'345)
    for (int offset : {-600, -150, 0, 60, 765}) {
      const UtcInstant instant{Duration{t}};
      const ZonedInstant back = parse_date_time(format_date_time(instant, offset), std::nullopt);
      BOOST_TEST_REQUIRE((back.utc == instant));
      BOOST_TEST_REQUIRE(back.offset_minutes == offset);
    }
}

// === Dates and steps

BOOST_AUTO_TEST_CASE(dates_parse_and_begin_at_local_midnight) {
  const CivilDate date = parse_date("2026-03-21");
  BOOST_TEST((date == CivilDate{2026, 3, 21}));
  BOOST_TEST((local_midnight(date, 0) == utc("2026-03-21T00:00:00Z")));
  BOOST_TEST((local_midnight(date, 60) == utc("2026-03-20T23:00:00Z")));
  BOOST_TEST((local_midnight(date, -300) == utc("2026-03-21T05:00:00Z")));
  check_refused([](const std::string& t) { parse_date(t); }, "2026-03-21T00:00",
                "expected YYYY-MM-DD only");
  check_refused([](const std::string& t) { parse_date(t); }, "2025-02-29", "(28 days)");
}

BOOST_AUTO_TEST_CASE(step_lengths_add_their_units) {
  BOOST_TEST(parse_step("10min").count() == 600 * kSecond);
  BOOST_TEST(parse_step("1h").count() == 3600 * kSecond);
  BOOST_TEST(parse_step("30s").count() == 30 * kSecond);
  BOOST_TEST(parse_step("1h30min").count() == 5400 * kSecond);
  BOOST_TEST(parse_step("2h15min30s").count() == (7200 + 900 + 30) * kSecond);
  BOOST_TEST(parse_step("90s").count() == 90 * kSecond);
  BOOST_TEST(parse_step("0h5min").count() == 300 * kSecond);
  check_step_refused("", "expected a number and a unit");
  check_step_refused("10", "has no unit");
  check_step_refused("10m", "\"m\" is ambiguous");
  check_step_refused("min", "expected a whole number");
  check_step_refused("10 min", "unknown unit \" min\"");
  check_step_refused("1.5h", "unknown unit \".\"");
  check_step_refused("30s1h", "largest first");
  check_step_refused("1h1h", "each at most once");
  check_step_refused("0min", "longer than zero");
  check_step_refused("10d", "unknown unit \"d\"");
  check_step_refused("1234567890s", "more than 9 digits");
}

BOOST_AUTO_TEST_CASE(steps_fall_on_multiples_of_the_step_from_local_midnight) {
  // 09:05 local (+01:00) to 10:00 every 10 minutes: 09:10, 09:20, ..., 10:00.
  const ZonedInstant from = parse_date_time("2026-03-21T09:05:00+01:00", std::nullopt);
  const auto steps = step_instants(from, utc("2026-03-21T10:00:00+01:00"), parse_step("10min"));
  BOOST_TEST_REQUIRE(steps.size() == 6u);
  BOOST_TEST(format_date_time(steps.front(), 60) == "2026-03-21T09:10:00+01:00");
  BOOST_TEST(format_date_time(steps.back(), 60) == "2026-03-21T10:00:00+01:00");
  // A start on the grid is included; so is an end on it.
  const auto exact = step_instants(parse_date_time("2026-03-21T09:00:00+01:00", std::nullopt),
                                   utc("2026-03-21T09:30:00+01:00"), parse_step("10min"));
  BOOST_TEST(exact.size() == 4u);
  // The grid is local: with +05:30 and whole hours the instants are at :30 UTC.
  const auto india = step_instants(parse_date_time("2026-03-21T06:00:00+05:30", std::nullopt),
                                   utc("2026-03-21T08:00:00+05:30"), parse_step("1h"));
  BOOST_TEST_REQUIRE(india.size() == 3u);
  BOOST_TEST(format_date_time(india[0], 0) == "2026-03-21T00:30:00+00:00");
  // 7 minutes from 09:05: 545 / 7 = 77.9, so the first is 78 * 7 = 546 min = 09:06.
  const auto seven = step_instants(from, utc("2026-03-21T09:30:00+01:00"), parse_step("7min"));
  BOOST_TEST_REQUIRE(seven.size() == 4u);  // 09:06, 09:13, 09:20, 09:27
  BOOST_TEST(format_date_time(seven[0], 60) == "2026-03-21T09:06:00+01:00");
  BOOST_TEST(format_date_time(seven[3], 60) == "2026-03-21T09:27:00+01:00");
}

BOOST_AUTO_TEST_CASE(steps_count_on_from_the_first_midnight) {
  // 25 minutes from 23:50: 1430 / 25 = 57.2, so 58 * 25 = 1450 min = 00:10 the next
  // day, then 00:35 (past the end). Not reset to 00:00 at the second midnight.
  const ZonedInstant from = parse_date_time("2026-03-21T23:50:00Z", std::nullopt);
  const auto steps = step_instants(from, utc("2026-03-22T00:30:00Z"), parse_step("25min"));
  BOOST_TEST_REQUIRE(steps.size() == 1u);
  BOOST_TEST(format_date_time(steps[0], 0) == "2026-03-22T00:10:00+00:00");
  // A whole day at 10 minutes: 24 * 6 + 1 instants, both midnights included.
  const auto day = step_instants(parse_date_time("2026-06-21T00:00:00+02:00", std::nullopt),
                                 utc("2026-06-22T00:00:00+02:00"), parse_step("10min"));
  BOOST_TEST(day.size() == 145u);
}

BOOST_AUTO_TEST_CASE(empty_ranges_and_bad_steps) {
  const ZonedInstant from = parse_date_time("2026-03-21T12:00:00Z", std::nullopt);
  BOOST_TEST(step_instants(from, utc("2026-03-21T11:59:59Z"), parse_step("1min")).empty());
  // Inside one step: nothing on the grid.
  BOOST_TEST(step_instants(parse_date_time("2026-03-21T12:01:00Z", std::nullopt),
                           utc("2026-03-21T12:09:00Z"), parse_step("10min"))
                 .empty());
  BOOST_CHECK_THROW(step_instants(from, from.utc, Duration{0}), std::invalid_argument);
  BOOST_CHECK_THROW(step_instants(from, from.utc, Duration{-1}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
