//! `#[covers]`, the attribute of every function of `proofs/` that holds a `cover!` (see
//! `proofs/cover.rs`).
//!
//! Kani counts, per harness, every cover in the code the harness can call, reached or not: a
//! cover in a branch the harness's inputs never take is reported unreachable and fails the
//! harness. `cargo test` only sees the covers it evaluates. The attribute closes that gap for
//! a function: it lists the messages of the `cover!(cond, "message")` calls in the function's
//! tokens and declares them all when the function is entered, so a harness that enters the
//! function counts each of its covers, taken branch or not. It also defines the item that
//! `cover!` refers to, so a `cover!` in a function without the attribute does not compile.

use proc_macro::{Delimiter, Group, Literal, TokenStream, TokenTree};

/// Declares on entry every cover of the function (the messages of its `cover!` calls, closures
/// included), and allows `cover!` in it.
#[proc_macro_attribute]
pub fn covers(attr: TokenStream, item: TokenStream) -> TokenStream {
    if !attr.is_empty() {
        return error("#[covers] takes no arguments");
    }
    let mut tokens: Vec<TokenTree> = item.into_iter().collect();
    let Some(TokenTree::Group(body)) = tokens.pop() else {
        return error("#[covers] goes on a function with a body");
    };
    if body.delimiter() != Delimiter::Brace {
        return error("#[covers] goes on a function with a body");
    }
    let mut messages = Vec::new();
    if let Err(e) = cover_messages(body.stream(), &mut messages) {
        return e;
    }
    let list: Vec<String> = messages.iter().map(Literal::to_string).collect();
    let prelude: TokenStream = format!(
        "#[allow(dead_code, non_upper_case_globals)] const __COVERS_DECLARED: () = (); \
         #[cfg(not(kani))] static __COVERS: crate::cover::Declared = \
         crate::cover::Declared::new(&[{}]); \
         #[cfg(not(kani))] __COVERS.enter();",
        list.join(", ")
    )
    .parse()
    .expect("the prelude is valid Rust");
    let mut new_body = prelude;
    new_body.extend(body.stream());
    let mut group = Group::new(Delimiter::Brace, new_body);
    group.set_span(body.span());
    tokens.push(TokenTree::Group(group));
    tokens.into_iter().collect()
}

/// The message of every `cover!(…, "message")` in `stream`, nested groups included.
fn cover_messages(stream: TokenStream, out: &mut Vec<Literal>) -> Result<(), TokenStream> {
    let tokens: Vec<TokenTree> = stream.into_iter().collect();
    for (i, t) in tokens.iter().enumerate() {
        let TokenTree::Group(g) = t else { continue };
        let is_cover = i >= 2
            && matches!(&tokens[i - 2], TokenTree::Ident(id) if id.to_string() == "cover")
            && matches!(&tokens[i - 1], TokenTree::Punct(p) if p.as_char() == '!')
            && g.delimiter() == Delimiter::Parenthesis;
        if is_cover {
            // The message is the last top-level token (before a trailing comma): a string literal.
            let last = g
                .stream()
                .into_iter()
                .filter(|t| !matches!(t, TokenTree::Punct(p) if p.as_char() == ','))
                .last();
            match last {
                Some(TokenTree::Literal(l)) if l.to_string().starts_with('"') => out.push(l),
                _ => {
                    return Err(error(
                        "cover!'s last argument is its message, a string literal",
                    ))
                }
            }
        }
        cover_messages(g.stream(), out)?;
    }
    Ok(())
}

/// A compile error with `msg`.
fn error(msg: &str) -> TokenStream {
    format!("compile_error!({msg:?});")
        .parse()
        .expect("a compile_error! call is valid Rust")
}
