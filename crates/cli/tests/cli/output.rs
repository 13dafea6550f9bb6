//! What `solve` prints: the figures with their pieces, a summary, progress
//! lines on stderr without a terminal, nothing with `--quiet`.

use crate::support::{assert_valid, clip, json, Sandbox};

fn pair(sb: &Sandbox) -> [String; 2] {
    [
        sb.copy_instance("squares-3-4-split-to-5", "a.txt", "a.txt"),
        sb.copy_instance("squares-3-4-split-to-5", "b.txt", "b.txt"),
    ]
}

#[test]
fn quiet_prints_nothing() {
    let sb = Sandbox::new();
    let [a, b] = pair(&sb);
    for flag in ["--quiet", "-q"] {
        let run = sb.run(&["solve", flag, "-o", "out.json", &a, &b]);
        run.expect_code(0);
        assert!(
            run.stdout.is_empty(),
            "{flag}: stdout\n{}",
            clip(&run.stdout)
        );
        assert!(
            run.stderr.is_empty(),
            "{flag}: stderr\n{}",
            clip(&run.stderr)
        );
        assert_valid(&sb, "square", "out.json", &[&a, &b]);
    }
}

#[test]
fn without_a_terminal_progress_is_one_plain_line_per_level() {
    let sb = Sandbox::new();
    let [a, b] = pair(&sb);
    let run = sb.run(&["solve", "--paper", "--no-prove", "-o", "out.json", &a, &b]);
    run.expect_code(0);
    assert!(
        !run.stderr.contains('\x1b') && !run.stderr.contains('\r'),
        "no terminal codes without a terminal:\n{:?}",
        run.stderr
    );
    let lines: Vec<&str> = run.stderr.lines().collect();
    let found_level = json(&sb.read("out.json"))["level"]
        .as_u64()
        .expect("level key") as usize;
    assert_eq!(
        lines.len(),
        found_level + 1,
        "one line per level:\n{}",
        run.stderr
    );
    for (level, line) in lines.iter().enumerate() {
        let pieces = level + 1;
        let head = format!(
            "level {level} ({pieces} piece{}): ",
            if pieces == 1 { "" } else { "s" }
        );
        assert!(
            line.starts_with(&head),
            "{line:?} should start with {head:?}"
        );
        assert!(
            line.contains("best E_M ") && line.ends_with(" s"),
            "{line:?}"
        );
        assert_eq!(
            line.contains("dissection found"),
            level == found_level,
            "{line:?}"
        );
    }
    // No colour codes on a pipe either, unless asked for.
    assert!(!run.stdout.contains('\x1b'));
    let coloured = sb.run(&["solve", "--color", "always", &a, &b]);
    coloured.expect_code(0);
    assert!(
        coloured.stdout.contains("\x1b[48;5;"),
        "{}",
        coloured.stdout
    );
}

#[test]
fn on_a_terminal_progress_is_a_bar() {
    // `script` (util-linux, part of every Debian) gives the run a terminal.
    let sb = Sandbox::new();
    let [a, b] = pair(&sb);
    let command = format!(
        "{} solve --paper --no-prove --color never -o out.json {a} {b}",
        env!("CARGO_BIN_EXE_dissect")
    );
    let out = std::process::Command::new("script")
        .args(["-qec", &command, "/dev/null"])
        .current_dir(sb.path("."))
        .stdin(std::process::Stdio::null())
        .output()
        .expect("`script` (util-linux) runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", clip(&text));
    assert!(!text.contains("panicked"), "{}", clip(&text));
    for part in [
        "level 1 (2 pieces) [",
        "/400 explorations, ",
        "level 1 (2 pieces): ",
    ] {
        assert!(
            text.contains(part),
            "no {part:?} on the terminal:\n{}",
            clip(&text)
        );
    }
    assert_valid(&sb, "square", "out.json", &[&a, &b]);
}

#[test]
fn solve_prints_each_figure_with_its_pieces_and_a_summary() {
    let sb = Sandbox::new();
    let [a, b] = pair(&sb);
    let run = sb.run(&["solve", "-o", "out.json", &a, &b]);
    run.expect_code(0);
    let sol = json(&sb.read("out.json"));
    let n = assert_valid(&sb, "square", "out.json", &[&a, &b]);
    let areas: Vec<usize> = sol["figures"][0]["pieces"]
        .as_array()
        .expect("pieces")
        .iter()
        .map(|p| p.as_array().expect("cells").len())
        .collect();
    let letters: Vec<String> = areas
        .iter()
        .enumerate()
        .map(|(i, a)| format!("{}={a}", (b'A' + i as u8) as char))
        .collect();
    // a.txt is 9 columns by 4 rows, b.txt 5 by 5: one character per cell.
    let text = &run.stdout;
    let at_a = text.find("a.txt:\n").expect("a.txt heading");
    let at_b = text.find("b.txt:\n").expect("b.txt heading");
    assert!(at_a < at_b);
    let drawing_a: Vec<&str> = text[at_a..at_b]
        .lines()
        .skip(1)
        .take_while(|l| !l.is_empty())
        .collect();
    assert_eq!(drawing_a.len(), 4);
    assert!(
        drawing_a.iter().all(|l| l.chars().count() == 9),
        "{drawing_a:?}"
    );
    assert_eq!(
        drawing_a[0].chars().nth(4),
        Some('.'),
        "the gap shows as '.'"
    );
    for (i, area) in areas.iter().enumerate() {
        let letter = (b'A' + i as u8) as char;
        let drawn = text[at_a..at_b].chars().filter(|c| *c == letter).count();
        assert_eq!(drawn, *area, "piece {letter} in a.txt");
    }
    run.stdout_has(&[
        &format!("\n{n} pieces\n"),
        &format!("piece areas: {}\n", letters.join(" ")),
        "area variance: ",
        "time: ",
    ]);
}

#[test]
fn three_figures_are_printed_and_written_in_order() {
    let sb = Sandbox::new();
    let rect = sb.write("rect.txt", "###\n###\n");
    let bar = sb.write("bar.txt", "######\n");
    let ell = sb.write("ell.txt", "#....\n#####\n");
    let run = sb.run(&["solve", "--seed", "3", "-o", "out.json", &rect, &bar, &ell]);
    run.expect_code(0);
    let n = assert_valid(&sb, "square", "out.json", &[&rect, &bar, &ell]);
    let sol = json(&sb.read("out.json"));
    let names: Vec<&str> = sol["figures"]
        .as_array()
        .expect("figures")
        .iter()
        .map(|f| f["name"].as_str().expect("name"))
        .collect();
    assert_eq!(names, ["rect.txt", "bar.txt", "ell.txt"]);
    let at: Vec<usize> = ["rect.txt:\n", "bar.txt:\n", "ell.txt:\n"]
        .iter()
        .map(|h| {
            run.stdout
                .find(h)
                .unwrap_or_else(|| panic!("{h} missing:\n{}", run.stdout))
        })
        .collect();
    assert!(at[0] < at[1] && at[1] < at[2], "{}", run.stdout);
    run.stdout_has(&[&format!("\n{n} pieces\n")]);
    // In the wrong order the pieces do not match the figures.
    let wrong = sb.run(&["verify", "--solution", "out.json", &bar, &rect, &ell]);
    wrong.expect_code(1).stdout_has(&[
        "invalid: ",
        "note: the solution lists the figures rect.txt, bar.txt, ell.txt",
    ]);
}

#[test]
fn a_closed_stdout_loses_nothing() {
    // `dissect solve ... | head -0`: the solution is still written, and
    // nothing panics.
    let sb = Sandbox::new();
    let [a, b] = pair(&sb);
    sb.run_with_closed_stdout(&["solve", "-o", "out.json", &a, &b])
        .expect_code(0);
    assert_valid(&sb, "square", "out.json", &[&a, &b]);
    sb.run_with_closed_stdout(&["info", &a, &b]).expect_code(0);
    sb.run_with_closed_stdout(&["verify", "--solution", "out.json", &a, &b])
        .expect_code(0);
}
