//! bubblewrap's arguments, piece by piece: the system read-only, the parents of what is
//! bound, the namespaces left.
//!
//! Course book: [The instructor's guide](../../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// The arguments that give a new root with the system's programs and libraries read-only:
/// `/usr` and the top-level links into it (or the directories, where they are not links).
pub(super) fn system(args: &mut Vec<OsString>) {
    push(args, ["--ro-bind", "/usr", "/usr"]);
    for top in ["/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"] {
        let p = Path::new(top);
        match std::fs::read_link(p) {
            Ok(to) => {
                args.push("--symlink".into());
                args.push(to.into_os_string());
                args.push(top.into());
            }
            Err(_) if p.is_dir() => push(args, ["--ro-bind", top, top]),
            Err(_) => {}
        }
    }
}

pub(super) fn push<const N: usize>(args: &mut Vec<OsString>, items: [&str; N]) {
    args.extend(items.iter().map(OsString::from));
}

pub(super) fn push_path(args: &mut Vec<OsString>, flag: &str, path: &Path) {
    args.push(flag.into());
    args.push(path.as_os_str().to_owned());
}

/// `--perms 0755 --dir D` for each ancestor of `path` not made yet, so that an unprivileged
/// user can reach what is bound below them (bubblewrap makes missing parents private).
pub(super) fn ancestors(args: &mut Vec<OsString>, made: &mut Vec<PathBuf>, path: &Path) {
    let mut chain: Vec<&Path> = path.ancestors().skip(1).collect();
    chain.reverse();
    for dir in chain {
        if dir.parent().is_none() || made.iter().any(|m| m == dir) {
            continue;
        }
        push(args, ["--perms", "0755"]);
        push_path(args, "--dir", dir);
        made.push(dir.to_path_buf());
    }
}

/// The namespaces to leave: all of them; as root, all but the user namespace (the test drops
/// to its own user instead, with `setpriv`).
pub(super) fn unshare(args: &mut Vec<OsString>, root: bool) {
    if root {
        push(
            args,
            [
                "--unshare-ipc",
                "--unshare-pid",
                "--unshare-net",
                "--unshare-uts",
                "--unshare-cgroup-try",
            ],
        );
    } else {
        push(args, ["--unshare-all"]);
    }
    push(args, ["--die-with-parent", "--new-session"]);
}
