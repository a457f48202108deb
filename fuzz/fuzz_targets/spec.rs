//! libFuzzer entry point: every input goes through [`harness::run`], shared with the corpus replay
//! in `tests/cli/robustness.rs`.

#![no_main]

#[path = "../harness.rs"]
mod harness;

libfuzzer_sys::fuzz_target!(|data: &[u8]| harness::run(data));
