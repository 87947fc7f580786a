//! WGSL text of the Rust emitter's expression tokens, for both WGSL writers (the module's
//! products and unary operations, and exp/log).

use proc_macro2::{Delimiter, TokenStream, TokenTree};

/// WGSL text of expression tokens: spaces around operators, none around `.` or inside
/// parentheses, and `self` (reserved in WGSL) read as `v`, the versor's parameter.
pub fn text(tokens: &TokenStream) -> String {
    let mut out = String::new();
    write_tokens(tokens.clone(), &mut out);
    out.trim().to_owned()
}

fn write_tokens(tokens: TokenStream, out: &mut String) {
    let word_end = |out: &String| {
        out.chars()
            .last()
            .is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ')')
    };
    for token in tokens {
        match token {
            TokenTree::Group(group) => {
                let (open, close) = match group.delimiter() {
                    Delimiter::Parenthesis => ("(", ")"),
                    Delimiter::Bracket => ("[", "]"),
                    Delimiter::Brace => ("{", "}"),
                    Delimiter::None => ("", ""),
                };
                out.push_str(open);
                write_tokens(group.stream(), out);
                let trimmed = out.trim_end().len();
                out.truncate(trimmed);
                out.push_str(close);
            }
            TokenTree::Ident(ident) => {
                if word_end(out) {
                    out.push(' ');
                }
                if ident == "self" {
                    out.push('v');
                } else {
                    out.push_str(&ident.to_string());
                }
            }
            TokenTree::Literal(literal) => {
                if word_end(out) {
                    out.push(' ');
                }
                out.push_str(&literal.to_string());
            }
            TokenTree::Punct(punct) => match punct.as_char() {
                '.' => out.push('.'),
                ',' => out.push_str(", "),
                ';' => out.push_str("; "),
                c => {
                    if !out.is_empty() && !out.ends_with([' ', '(']) {
                        out.push(' ');
                    }
                    out.push(c);
                    // A unary minus binds to what follows; a binary operator is spaced.
                    let unary = out.len() == 1
                        || out[..out.len() - 1]
                            .trim_end()
                            .ends_with(['(', ',', '=', '-', '+', '*', '/']);
                    if !(c == '-' && unary) {
                        out.push(' ');
                    }
                }
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use quote::quote;

    use super::*;

    #[test]
    fn tokens_print_as_wgsl_expressions() {
        let tokens = quote!((self.s * b.e1 + -a.e12 * b.e2) - 2.0 * (x.e1));
        assert_eq!(text(&tokens), "(v.s * b.e1 + -a.e12 * b.e2) - 2.0 * (x.e1)");
        assert_eq!(text(&quote!(-a.s)), "-a.s");
        assert_eq!(
            text(&quote!(Even(a.s, -(a.e1 - b.e1)))),
            "Even(a.s, -(a.e1 - b.e1))"
        );
    }
}
