//! The math text of a live page (`mathtext.js`): the script runs and italic variables of a label,
//! set as the drawn figures set them (`output::plot::mathtext`); a test holds the two to the same
//! slant on a set of labels.

/// The page's math text script; it defines `ndfplotMathRuns(text)` → `[{text, scale, rise, italic}]`.
pub(super) const SCRIPT: &str = include_str!("mathtext.js");

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::slanted_letters;
    use std::process::Command;

    /// Labels with every case of the slant rule: lone letters, words, subscripts, articles,
    /// elisions, constants and panel letters.
    const LABELS: [&str; 14] = [
        "θ (radians)",
        "G_1(θ_o) (1 + Λ(θ_o))",
        "ln D(θ) and cos θ",
        "E_{avg} = 0.41",
        "a reference for a_1",
        "α_{tr} = 0.4 … 0.9",
        "ABC 2048",
        "π/6 and Σ x",
        "the notebook's α and θ'",
        "(b) D(θ) of (a)",
        "D_{fit}(θ) / D_{ABC}(θ)",
        "Schlick's F_0 at η = 1.5",
        "pbrt-v4 α = √r",
        "Student-t",
    ];

    #[test]
    fn the_page_slants_the_letters_the_figures_slant() {
        if !matches!(Command::new("node").arg("--version").output(), Ok(out) if out.status.success())
        {
            eprintln!(
                "SKIPPED the_page_slants_the_letters_the_figures_slant: node is not installed"
            );
            return;
        }
        let labels = serde_json::to_string(&LABELS).unwrap();
        let program = format!(
            "{SCRIPT}\nconsole.log(JSON.stringify({labels}.map((t) => ndfplotMathRuns(t).filter((r) => r.italic).map((r) => r.text).join(''))));"
        );
        let out = Command::new("node")
            .arg("-e")
            .arg(&program)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "node: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let page: Vec<String> = serde_json::from_slice(&out.stdout).unwrap();
        for (label, page) in LABELS.iter().zip(&page) {
            assert_eq!(*page, slanted_letters(label), "{label}");
        }
    }
}
