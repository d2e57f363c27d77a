//! A kernel program on the other end of two pipes, as a
//! [`CaseKernel`]: case lines out, answer lines in, with a time limit.

use rayoracle::case::Case;
use rayoracle::check::gate::protocol::{case_line, read_answer};
use rayoracle::check::gate::{CaseKernel, Reply};
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError, Sender, channel};
use std::time::Duration;

/// A kernel program: case lines to its stdin (from a writer thread, so a
/// full pipe never blocks the reader), answer lines from its stdout (from
/// a reader thread, so a hang is a timeout).
pub struct Program {
    name: String,
    child: Child,
    to_writer: Option<Sender<Vec<String>>>,
    from_reader: Receiver<io::Result<String>>,
    timeout: Duration,
    next_id: u64,
    lines_read: usize,
    dead: Option<String>,
    /// The family of each case of the first batch, by id.
    pub families: Vec<String>,
    /// The family of the failure being shrunk, for the later cases.
    shrinking: String,
    /// Answer lines read, on stderr when it is a terminal.
    pub bar: indicatif::ProgressBar,
}

impl Program {
    pub fn start(program: &[String], timeout: Duration) -> io::Result<Program> {
        let mut child = Command::new(&program[0])
            .args(&program[1..])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()?;
        let stdin = child.stdin.take().expect("stdin was piped");
        let stdout = child.stdout.take().expect("stdout was piped");
        let (to_writer, batches) = channel::<Vec<String>>();
        std::thread::spawn(move || write_batches(stdin, batches));
        let (lines, from_reader) = channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                let end = line.is_err();
                if lines.send(line).is_err() || end {
                    break;
                }
            }
        });
        Ok(Program {
            name: program.join(" "),
            child,
            to_writer: Some(to_writer),
            from_reader,
            timeout,
            next_id: 0,
            lines_read: 0,
            dead: None,
            families: Vec::new(),
            shrinking: String::new(),
            bar: indicatif::ProgressBar::hidden(),
        })
    }

    /// Closes the program's stdin and waits briefly for it; kills it if it
    /// does not end.
    pub fn stop(&mut self) {
        self.to_writer = None;
        for _ in 0..50 {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(10));
        }
        kill_tree(&mut self.child);
    }

    /// How the program ended, if it has.
    fn exit_status(&mut self) -> String {
        std::thread::sleep(Duration::from_millis(20));
        match self.child.try_wait() {
            Ok(Some(s)) => format!("exited ({s})"),
            _ => "closed its stdout".into(),
        }
    }
}

/// Kills the program and, on Linux, every process under it: a kernel run
/// through a shell or a package runner (`sh -c`, `npm run`) is a
/// grandchild, which would otherwise outlive the gate, still holding the
/// pipes (and the terminal's stderr) it inherited. The processes are
/// listed before any is killed, since an orphan loses its parent id.
fn kill_tree(child: &mut Child) {
    #[cfg(target_os = "linux")]
    for pid in descendants(child.id()) {
        if let Some(pid) = rustix::process::Pid::from_raw(pid) {
            let _ = rustix::process::kill_process(pid, rustix::process::Signal::KILL);
        }
    }
    let _ = child.kill();
    let _ = child.wait();
}

/// The processes below `root`, from the parent ids in `/proc/*/stat`.
#[cfg(target_os = "linux")]
fn descendants(root: u32) -> Vec<i32> {
    let parent = |e: std::fs::DirEntry| -> Option<(i32, i32)> {
        let pid = e.file_name().to_str()?.parse().ok()?;
        let stat = std::fs::read_to_string(e.path().join("stat")).ok()?;
        // "pid (comm) state ppid …", where comm may hold spaces and ')'.
        let ppid = stat.rsplit_once(')')?.1.split_whitespace().nth(1)?;
        Some((pid, ppid.parse().ok()?))
    };
    let links: Vec<(i32, i32)> = std::fs::read_dir("/proc")
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(parent)
        .collect();
    let (mut found, mut next) = (Vec::new(), vec![root as i32]);
    while let Some(p) = next.pop() {
        for &(pid, pp) in &links {
            if pp == p && !found.contains(&pid) {
                found.push(pid);
                next.push(pid);
            }
        }
    }
    found
}

fn write_batches(stdin: ChildStdin, batches: Receiver<Vec<String>>) {
    let mut w = BufWriter::new(stdin);
    for batch in batches {
        for line in batch {
            if writeln!(w, "{line}").is_err() {
                return; // the program is gone; the reader reports it
            }
        }
        if w.flush().is_err() {
            return;
        }
    }
}

impl CaseKernel for Program {
    fn shrinking(&mut self, family: &str) {
        self.shrinking = family.to_string();
    }

    fn answer(&mut self, cases: &[Case], replies: &mut Vec<Reply>) -> Result<(), String> {
        if let Some(why) = &self.dead {
            return Err(why.clone());
        }
        let first = self.next_id;
        let lines = cases
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let id = first + i as u64;
                let family = self.families.get(id as usize).unwrap_or(&self.shrinking);
                case_line(c, family, id)
            })
            .collect();
        self.next_id += cases.len() as u64;
        if let Some(w) = &self.to_writer {
            let _ = w.send(lines);
        }
        for (i, case) in cases.iter().enumerate() {
            let id = first + i as u64;
            let line_no = self.lines_read + 1;
            let why = match self.from_reader.recv_timeout(self.timeout) {
                Ok(Ok(line)) => {
                    self.lines_read += 1;
                    self.bar.inc(1);
                    replies.push(match read_answer(&line, case) {
                        Ok(a) if a.id.is_some_and(|x| x != id) => Reply::Failed(format!(
                            "answer line {line_no} has id {}, but answers the case of id {id}",
                            a.id.unwrap_or(0)
                        )),
                        Ok(a) => a.reply,
                        Err(e) => Reply::Failed(format!(
                            "answer line {line_no} is malformed: {e}: {}",
                            clip(&line)
                        )),
                    });
                    continue;
                }
                Ok(Err(e)) => format!("reading answer line {line_no} failed: {e}"),
                Err(RecvTimeoutError::Disconnected) => {
                    let status = self.exit_status();
                    format!(
                        "{} {status} after {} answer lines, without answering the case of id {id}",
                        self.name, self.lines_read
                    )
                }
                Err(RecvTimeoutError::Timeout) => {
                    kill_tree(&mut self.child);
                    format!(
                        "{} gave no answer line {line_no} (the case of id {id}) within {:?}, so it was stopped; answer lines must end with a newline and be flushed",
                        self.name, self.timeout
                    )
                }
            };
            self.dead = Some(why.clone());
            return Err(why);
        }
        Ok(())
    }
}

/// At most 80 characters of a line, for messages.
fn clip(line: &str) -> String {
    if line.chars().count() > 80 {
        format!("{}…", line.chars().take(80).collect::<String>())
    } else {
        line.to_string()
    }
}
