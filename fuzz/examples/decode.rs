//! Prints what a fuzz input decodes to, for turning a crash into a regression test: the
//! points, one `[x, y]` a line with every bit kept (`Debug` of `f64` round-trips), and for
//! the `eval` target's layout (`--eval`) also the result and ground-truth edges.
//!
//! `cargo run --example decode -- [--eval] FILE`
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (eval, path) = match args.as_slice() {
        [flag, path] if flag == "--eval" => (true, path),
        [path] => (false, path),
        _ => panic!("usage: decode [--eval] FILE"),
    };
    let data = std::fs::read(path).expect("readable file");
    if !eval {
        for [x, y] in sigdt_fuzz::points(&data) {
            println!("[{x:?}, {y:?}],");
        }
        return;
    }
    let (points, result, gt) = sigdt_fuzz::eval_input(&data).unwrap_or_default();
    for [x, y] in &points {
        println!("[{x:?}, {y:?}],");
    }
    println!("result: {result:?}\ngt: {gt:?}");
}
