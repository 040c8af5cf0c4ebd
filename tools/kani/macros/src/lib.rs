//! The attributes and the `Arbitrary` derive of the `kani` stand-in (`tools/kani`, see its
//! README). Each attribute checks its arguments as Kani documents them and returns the item
//! unchanged, so that a misspelt solver or an unwind bound that is not a number fails the build
//! here as it would under `cargo kani`; none of them makes anything a proof.

use proc_macro::TokenStream;
use proc_macro2::Span;
use quote::quote;
use syn::{parse_macro_input, Data, DeriveInput, Fields, ItemFn};

/// Fails with `msg` at `span`.
fn error(span: Span, msg: &str) -> TokenStream {
    syn::Error::new(span, msg).to_compile_error().into()
}

/// `#[kani::proof]`: marks a harness. Kani requires a function without parameters or generic
/// parameters; the stand-in checks that and keeps the function (allowed to be unused, since only
/// Kani calls it).
#[proc_macro_attribute]
pub fn proof(attr: TokenStream, item: TokenStream) -> TokenStream {
    if !attr.is_empty() {
        return error(Span::call_site(), "#[kani::proof] takes no arguments");
    }
    let f = parse_macro_input!(item as ItemFn);
    if !f.sig.inputs.is_empty() || !f.sig.generics.params.is_empty() {
        return error(
            Span::call_site(),
            "a Kani harness takes no parameters and no generic parameters",
        );
    }
    quote!(#[allow(dead_code)] #f).into()
}

/// `#[kani::unwind(n)]`: the loop unwinding bound of a harness, a non-negative integer.
#[proc_macro_attribute]
pub fn unwind(attr: TokenStream, item: TokenStream) -> TokenStream {
    match syn::parse::<syn::LitInt>(attr) {
        Ok(n) if n.base10_parse::<u32>().is_ok() => item,
        Ok(n) => error(n.span(), "#[kani::unwind(n)]: n is a non-negative integer"),
        Err(e) => e.to_compile_error().into(),
    }
}

/// `#[kani::solver(s)]`: the SAT solver of a harness: `cadical`, `kissat`, `minisat` or
/// `bin = "name"` (an executable on the path).
#[proc_macro_attribute]
pub fn solver(attr: TokenStream, item: TokenStream) -> TokenStream {
    let ok = if let Ok(id) = syn::parse::<syn::Ident>(attr.clone()) {
        matches!(id.to_string().as_str(), "cadical" | "kissat" | "minisat")
    } else if let Ok(nv) = syn::parse::<syn::MetaNameValue>(attr) {
        nv.path.is_ident("bin")
            && matches!(&nv.value, syn::Expr::Lit(l) if matches!(l.lit, syn::Lit::Str(_)))
    } else {
        false
    };
    if ok {
        item
    } else {
        error(
            Span::call_site(),
            "#[kani::solver(..)] takes cadical, kissat, minisat or bin = \"name\"",
        )
    }
}

/// `#[kani::should_panic]`: the harness is expected to fail.
#[proc_macro_attribute]
pub fn should_panic(attr: TokenStream, item: TokenStream) -> TokenStream {
    if !attr.is_empty() {
        return error(
            Span::call_site(),
            "#[kani::should_panic] takes no arguments",
        );
    }
    item
}

/// `#[kani::proof_for_contract(f)]`: a harness that checks the contract of `f` (a path); like
/// [`macro@proof`], a function without parameters.
#[proc_macro_attribute]
pub fn proof_for_contract(attr: TokenStream, item: TokenStream) -> TokenStream {
    if syn::parse::<syn::Path>(attr).is_err() {
        return error(
            Span::call_site(),
            "#[kani::proof_for_contract(f)] names the function whose contract it checks",
        );
    }
    proof(TokenStream::new(), item)
}

/// The contract and stubbing attributes (`requires`, `ensures`, `modifies`, `recursion`,
/// `stub`, `stub_verified`): kept as written; only Kani reads them.
macro_rules! pass_through {
    ($($(#[$doc:meta])* $name:ident;)*) => {$(
        $(#[$doc])*
        #[proc_macro_attribute]
        pub fn $name(_attr: TokenStream, item: TokenStream) -> TokenStream {
            item
        }
    )*};
}

pass_through! {
    /// `#[kani::requires(cond)]`: a precondition of a function contract.
    requires;
    /// `#[kani::ensures(|result| cond)]`: a postcondition of a function contract.
    ensures;
    /// `#[kani::modifies(place, ..)]`: what a function contract may modify.
    modifies;
    /// `#[kani::recursion]`: the function is recursive (for contracts).
    recursion;
    /// `#[kani::stub(original, replacement)]`: replaces a function in a harness.
    stub;
    /// `#[kani::stub_verified(f)]`: replaces a function by its verified contract.
    stub_verified;
}

/// `#[derive(kani::Arbitrary)]`: `any()` builds the value from `kani::any()` of each field
/// (for an enum, of a variant chosen by `kani::any()`); each type parameter must be `Arbitrary`.
#[proc_macro_derive(Arbitrary)]
pub fn derive_arbitrary(item: TokenStream) -> TokenStream {
    let input = parse_macro_input!(item as DeriveInput);
    let name = &input.ident;
    let mut generics = input.generics.clone();
    for p in generics.type_params_mut() {
        p.bounds.push(syn::parse_quote!(::kani::Arbitrary));
    }
    let (impl_g, ty_g, where_c) = generics.split_for_impl();
    let fields = |f: &Fields| match f {
        Fields::Named(n) => {
            let names = n.named.iter().map(|f| &f.ident);
            quote!({ #(#names: ::kani::any(),)* })
        }
        Fields::Unnamed(u) => {
            let anys = u.unnamed.iter().map(|_| quote!(::kani::any()));
            quote!(( #(#anys,)* ))
        }
        Fields::Unit => quote!(),
    };
    let body = match &input.data {
        Data::Struct(s) => {
            let f = fields(&s.fields);
            quote!(Self #f)
        }
        Data::Enum(e) if e.variants.is_empty() => {
            return error(
                name.span(),
                "kani::Arbitrary cannot be derived for an empty enum",
            );
        }
        Data::Enum(e) => {
            let n = e.variants.len();
            let arms = e.variants.iter().enumerate().map(|(i, v)| {
                let vn = &v.ident;
                let f = fields(&v.fields);
                if i + 1 == n {
                    quote!(_ => Self::#vn #f,)
                } else {
                    quote!(#i => Self::#vn #f,)
                }
            });
            quote!(match ::kani::any::<usize>() % #n { #(#arms)* })
        }
        Data::Union(_) => {
            return error(name.span(), "kani::Arbitrary cannot be derived for a union");
        }
    };
    quote!(
        impl #impl_g ::kani::Arbitrary for #name #ty_g #where_c {
            fn any() -> Self {
                #body
            }
        }
    )
    .into()
}
