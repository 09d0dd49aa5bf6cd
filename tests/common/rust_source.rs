//! Just enough Rust lexing to read the test sources themselves (tests/test_lint.rs,
//! tests/validation_table.rs): literals masked, comments dropped, functions found with their
//! bodies.

/// `code` with the contents of string and char literals replaced by spaces and `//` comments
/// (doc comments included) blanked, byte for byte: offsets and line numbers are those of
/// `code`, and braces or keywords inside literals or comments no longer count.
pub fn mask(code: &str) -> String {
    let b = code.as_bytes();
    let mut out = b.to_vec();
    let mut i = 0;
    let blank = |out: &mut Vec<u8>, from: usize, to: usize| {
        for c in &mut out[from..to] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
    };
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => {
                let end = code[i..].find('\n').map_or(b.len(), |e| i + e);
                blank(&mut out, i, end);
                i = end;
            }
            b'r' if matches!(b.get(i + 1), Some(b'"' | b'#'))
                && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_')) =>
            {
                let hashes = b[i + 1..].iter().take_while(|&&c| c == b'#').count();
                if b.get(i + 1 + hashes) != Some(&b'"') {
                    i += 1;
                    continue;
                }
                let open = i + 2 + hashes;
                let close = format!("\"{}", "#".repeat(hashes));
                let end = code[open..].find(&close).map_or(b.len(), |e| open + e);
                blank(&mut out, open, end);
                i = end + close.len();
            }
            b'"' => {
                let mut j = i + 1;
                while j < b.len() && b[j] != b'"' {
                    j += if b[j] == b'\\' { 2 } else { 1 };
                }
                blank(&mut out, i + 1, j.min(b.len()));
                i = j + 1;
            }
            b'\'' => {
                // A char literal ('x', '\n', '{', '"') — not a lifetime ('a).
                let len = if b.get(i + 1) == Some(&b'\\') {
                    b.get(i + 3..)
                        .and_then(|r| r.iter().position(|&c| c == b'\''))
                        .map(|p| p + 4)
                } else {
                    let ch = code[i + 1..].chars().next().map_or(1, char::len_utf8);
                    (b.get(i + 1 + ch) == Some(&b'\'')).then_some(ch + 2)
                };
                match len {
                    Some(n) => {
                        blank(&mut out, i + 1, i + n - 1);
                        i += n;
                    }
                    None => i += 1,
                }
            }
            _ => i += 1,
        }
    }
    String::from_utf8(out).expect("only whole characters are blanked")
}

/// The functions of masked source `m`: (name, 1-based line of `fn`, byte range of the body
/// from its `{` to the matching `}`), declarations without a body skipped. With `macros`,
/// `macro_rules!` definitions count too.
pub fn functions(m: &str, macros: bool) -> Vec<(String, usize, std::ops::Range<usize>)> {
    let b = m.as_bytes();
    let mut out = Vec::new();
    let heads: &[&str] = if macros { &["fn ", "macro_rules! "] } else { &["fn "] };
    for head in heads {
        let mut from = 0;
        while let Some(off) = m[from..].find(head) {
            let at = from + off;
            from = at + head.len();
            if at > 0 && (b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_') {
                continue;
            }
            let name: String = m[from..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if name.is_empty() {
                continue;
            }
            // The body opens at the first `{` outside parentheses and brackets; a `;` there
            // first ends a declaration.
            let mut depth = 0i32;
            let mut open = None;
            for (i, &c) in b[from..].iter().enumerate() {
                match c {
                    b'(' | b'[' => depth += 1,
                    b')' | b']' => depth -= 1,
                    b';' if depth == 0 => break,
                    b'{' if depth == 0 => {
                        open = Some(from + i);
                        break;
                    }
                    _ => {}
                }
            }
            let Some(open) = open else { continue };
            let mut depth = 0usize;
            let mut end = b.len() - 1;
            for (i, &c) in b[open..].iter().enumerate() {
                match c {
                    b'{' => depth += 1,
                    b'}' => {
                        depth -= 1;
                        if depth == 0 {
                            end = open + i;
                            break;
                        }
                    }
                    _ => {}
                }
            }
            let line = m[..at].matches('\n').count() + 1;
            out.push((name, line, open..end + 1));
        }
    }
    out
}
