/// {fmt}'s compiled part, once, in geardyn (issue 34). With FMT_HEADER_ONLY every translation
/// unit compiled fmt/format-inl.h: 4-5 s of compile each, 110 units. Debian's libfmt.so is
/// not an option: the command line links libstdc++ statically (issue 22) and libfmt.so would
/// bring the shared one back. So the headers are used in their compiled mode everywhere and
/// the definitions they leave out (format-inl.h) are compiled here, with the instantiations that
/// fmt/format.h declares `extern template` or leaves undefined for char and wchar_t (dragonbox
/// for float and double, the locale accessors).
#include <fmt/format-inl.h>

FMT_BEGIN_NAMESPACE
namespace detail {

template auto dragonbox::to_decimal(float x) noexcept -> dragonbox::decimal_fp<float>;
template auto dragonbox::to_decimal(double x) noexcept -> dragonbox::decimal_fp<double>;

template locale_ref::locale_ref(const std::locale& loc);
template auto locale_ref::get<std::locale>() const -> std::locale;

template auto thousands_sep_impl(locale_ref) -> thousands_sep_result<char>;
template auto decimal_point_impl(locale_ref) -> char;
template auto thousands_sep_impl(locale_ref) -> thousands_sep_result<wchar_t>;
template auto decimal_point_impl(locale_ref) -> wchar_t;

}  // namespace detail
FMT_END_NAMESPACE
