//! The sandbox cargo builds the student's code in ([`Sandbox::build_wrapper`]): a body's
//! `include_str!`, `include_bytes!` or `#[path]` can read only what it shows.
//!
//! Course book: [The instructor's guide](../../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::path::{Path, PathBuf};

use super::bwrap::{push, push_path, system, unshare};
use super::policy::Level;
use super::worker::Sandbox;
use crate::cargo::Wrapper;

impl Sandbox {
    /// The wrapper cargo builds in: the system (`/usr`, of `/etc` what the linker needs), the
    /// toolchain and the registry (never cargo's credentials) read-only, the graded copy `project` read-only, the build directory `target_dir` writable, a private
    /// `/tmp`, no network; its environment only what cargo needs.
    /// `None` at [`Level::User`] and [`Level::Off`], whose build is not sandboxed.
    #[must_use]
    pub fn build_wrapper(&self, project: &Path, target_dir: &Path) -> Option<Wrapper> {
        if self.policy.level != Level::Namespaces {
            return None;
        }
        let mut args = Vec::new();
        unshare(&mut args, self.policy.uid.is_some());
        system(&mut args);
        // of /etc only what the linker needs (`cc` is a link through the alternatives; the
        // dynamic linker's cache): the build runs as the grader's user, and a body's
        // include_bytes! must find nothing of the machine's own there
        for etc in [
            "/etc/alternatives",
            "/etc/ld.so.cache",
            "/etc/ld.so.conf",
            "/etc/ld.so.conf.d",
        ] {
            if Path::new(etc).exists() {
                push(&mut args, ["--ro-bind", etc, etc]);
            }
        }
        push(
            &mut args,
            ["--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp"],
        );
        let home = std::env::var_os("HOME").map(PathBuf::from);
        let cargo_home = std::env::var_os("CARGO_HOME")
            .map(PathBuf::from)
            .or_else(|| home.as_ref().map(|h| h.join(".cargo")));
        let rustup_home = std::env::var_os("RUSTUP_HOME")
            .map(PathBuf::from)
            .or_else(|| home.as_ref().map(|h| h.join(".rustup")));
        let mut read: Vec<PathBuf> = Vec::new();
        if let Some(c) = &cargo_home {
            // the programs, the crates and the settings: never the credentials
            for part in ["bin", "registry", "git", "config.toml", "config"] {
                read.push(c.join(part));
            }
        }
        read.extend(rustup_home.iter().cloned());
        // a toolchain outside both homes ($CARGO set by a cargo that started us)
        if let Some(cargo) = std::env::var_os("CARGO").map(PathBuf::from)
            && let Some(toolchain) = cargo.parent().and_then(Path::parent)
            && !read.iter().any(|r| toolchain.starts_with(r))
            && !toolchain.starts_with("/usr")
        {
            read.push(toolchain.to_path_buf());
        }
        for p in read.iter().filter(|p| p.exists()) {
            push_path(&mut args, "--ro-bind", p);
            args.push(p.as_os_str().to_owned());
        }
        push_path(&mut args, "--bind", target_dir);
        args.push(target_dir.as_os_str().to_owned());
        // the copy after the build directory: it may lie inside it, and stays read-only
        push_path(&mut args, "--ro-bind", project);
        args.push(project.as_os_str().to_owned());
        push_path(&mut args, "--chdir", project);
        args.push("--".into());
        let mut env: Vec<(OsString, OsString)> = vec![
            ("CARGO_NET_OFFLINE".into(), "true".into()),
            ("TMPDIR".into(), "/tmp".into()),
            ("HOME".into(), "/tmp".into()),
        ];
        if let Some(c) = cargo_home {
            env.push(("CARGO_HOME".into(), c.into_os_string()));
        }
        if let Some(r) = rustup_home {
            env.push(("RUSTUP_HOME".into(), r.into_os_string()));
        }
        for (k, v) in std::env::vars_os() {
            let name = k.to_string_lossy();
            let keep = name == "PATH"
                || name == "RUSTUP_TOOLCHAIN"
                || name == "RUSTFLAGS"
                || name == "CARGO_INCREMENTAL"
                || name == "CARGO"
                || name.starts_with("CARGO_PROFILE_")
                || name.starts_with("CARGO_BUILD_");
            if keep {
                env.push((k, v));
            }
        }
        Some(Wrapper {
            program: self.policy.bwrap.clone().into_os_string(),
            args,
            env,
        })
    }
}
