//! The one way a closed set of choices is named in curve JSON and on the command line.
//!
//! An enum of unit variants declared with [`named!`] states each variant's name once, beside the
//! variant, and gets from that one table its `NAMES` (name and value, in declaration order: the
//! order messages, `--help` and the JSON Schema list them in), `ALL`, `name()` and `from_name()`.

/// Declares an enum whose unit variants each carry their name (`Variant = "name",`), deriving
/// `Debug, Clone, Copy, PartialEq, Eq, Hash`, with `NAMES`, `ALL`, `name()` and `from_name()`.
macro_rules! named {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident {
            $( $(#[$vmeta:meta])* $variant:ident = $text:literal, )+
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        $vis enum $name {
            $( $(#[$vmeta])* $variant, )+
        }

        impl $name {
            /// Every value with its name, in declaration order.
            pub const NAMES: [(&'static str, $name); [$($text),+].len()] =
                [$(($text, $name::$variant)),+];

            /// Every value, in declaration order.
            pub const ALL: [$name; [$($text),+].len()] = [$($name::$variant),+];

            /// The value's name in curve JSON or on the command line.
            pub fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $text,)+
                }
            }

            /// The value named `name` in any case (`Height-Correlated`), if any.
            pub fn from_name(name: &str) -> Option<$name> {
                Self::NAMES
                    .iter()
                    .find(|(n, _)| n.eq_ignore_ascii_case(name))
                    .map(|&(_, v)| v)
            }
        }
    };
}

pub(crate) use named;

#[cfg(test)]
mod tests {
    named! {
        /// A test enum.
        enum Choice {
            /// The first.
            First = "first",
            /// The second.
            Second = "second-one",
        }
    }

    #[test]
    fn names_round_trip_in_declaration_order() {
        assert_eq!(
            Choice::NAMES,
            [("first", Choice::First), ("second-one", Choice::Second)]
        );
        assert_eq!(Choice::ALL, [Choice::First, Choice::Second]);
        for (name, value) in Choice::NAMES {
            assert_eq!(value.name(), name);
            assert_eq!(Choice::from_name(name), Some(value));
        }
        assert_eq!(Choice::from_name("First"), Some(Choice::First));
        assert_eq!(Choice::from_name("SECOND-ONE"), Some(Choice::Second));
        assert_eq!(Choice::from_name("third"), None);
    }
}
