#pragma once
// Which protocols this build has (OCU_PROTOCOLS; tests/CMakeLists.txt defines OCU_TEST_WITH_<P>): a test of
// the whole console checks each protocol's part where the build has that protocol.
namespace ocutest {

#ifdef OCU_TEST_WITH_JAUS
inline constexpr bool kWithJaus = true;
#else
inline constexpr bool kWithJaus = false;
#endif
#ifdef OCU_TEST_WITH_ISO23725
inline constexpr bool kWithIso23725 = true;
#else
inline constexpr bool kWithIso23725 = false;
#endif
#ifdef OCU_TEST_WITH_OSYRIS
inline constexpr bool kWithOsyris = true;
#else
inline constexpr bool kWithOsyris = false;
#endif

} // namespace ocutest
