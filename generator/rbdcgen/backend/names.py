"""Turning robot, body, joint and foot names into C++ identifiers (Jinja2 filters and render code)."""
import re

CPP_KEYWORDS = frozenset("""
alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t char32_t
class compl concept const consteval constexpr constinit const_cast continue co_await co_return co_yield
decltype default delete do double dynamic_cast else enum explicit export extern false float for friend
goto if inline int long mutable namespace new noexcept not not_eq nullptr operator or or_eq private
protected public register reinterpret_cast requires return short signed sizeof static static_assert
static_cast struct switch template this thread_local throw true try typedef typeid typename union
unsigned using virtual void volatile wchar_t while xor xor_eq
""".split())


def cpp_identifier(name: str) -> str:
    """A valid C++ identifier close to `name`.

    >>> cpp_identifier("LF-hip joint")
    'LF_hip_joint'
    >>> cpp_identifier("3dof")
    '_3dof'
    >>> cpp_identifier("delete")
    'delete_'
    """
    identifier = re.sub(r"[^A-Za-z0-9_]", "_", name) or "_"
    if identifier[0].isdigit():
        identifier = "_" + identifier
    if identifier in CPP_KEYWORDS:
        identifier += "_"
    return identifier


def unique_identifiers(names: list[str]) -> list[str]:
    """cpp_identifier of each name, with a numeric suffix where two names would collide.

    >>> unique_identifiers(["a-b", "a_b", "c"])
    ['a_b', 'a_b_2', 'c']
    """
    seen: set[str] = set()
    result = []
    for name in names:
        identifier = base = cpp_identifier(name)
        suffix = 2
        while identifier in seen:
            identifier = f"{base}_{suffix}"
            suffix += 1
        seen.add(identifier)
        result.append(identifier)
    return result
