//! The integer type of an IEC counter as the Python classes name it (`type="INT"`), with its
//! range. Kept here, out of the trace engine, which now takes the data type from the core
//! (`plc_timers::catalog::DataType`); the blocks' rewrite onto the core interface replaces it.

use plc_timers::counter::CounterInt;

macro_rules! int_types {
    ($($variant:ident = $t:ty),* $(,)?) => {
        /// The integer type of an IEC counter; the names are the core's [`CounterInt::NAME`].
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum IntType {
            $(
                #[doc = concat!("`", stringify!($t), "`.")]
                $variant,
            )*
        }

        impl IntType {
            /// Every type.
            pub const ALL: [IntType; 8] = [$(IntType::$variant),*];

            /// The type's name (`SINT`, `INT`, …).
            pub fn name(self) -> &'static str {
                match self { $(IntType::$variant => <$t as CounterInt>::NAME,)* }
            }

            /// The smallest and the largest value.
            pub fn limits(self) -> (i128, i128) {
                match self {
                    $(IntType::$variant => (
                        <$t as CounterInt>::MIN.to_i128(),
                        <$t as CounterInt>::MAX.to_i128(),
                    ),)*
                }
            }
        }
    };
}

int_types!(
    SInt = i8,
    Int = i16,
    DInt = i32,
    LInt = i64,
    USInt = u8,
    UInt = u16,
    UDInt = u32,
    ULInt = u64
);

impl IntType {
    /// The type called `name` (ASCII case ignored).
    pub fn lookup(name: &str) -> Option<IntType> {
        IntType::ALL
            .into_iter()
            .find(|t| t.name().eq_ignore_ascii_case(name))
    }

    /// Every name, separated by blanks.
    pub fn names() -> String {
        let names: Vec<&str> = IntType::ALL.iter().map(|t| t.name()).collect();
        names.join(" ")
    }
}
