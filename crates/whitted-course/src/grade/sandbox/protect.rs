//! At the user level, the secrets kept from the tests by their permissions: the instructor's
//! project and the hidden tests must be closed to other users, and the graded copy is closed
//! while the hidden tests are in it.
//!
//! Course book: [The instructor's guide](../../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;

use super::policy::Level;
use super::worker::Sandbox;
use crate::ToolError;

/// Whether a user other than the owner can reach `path`: every directory from the root to it
/// searchable by others (and the path itself readable, when it is a file).
fn open_to_others(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    let Ok(path) = path.canonicalize() else {
        return false;
    };
    path.ancestors().all(|a| {
        std::fs::metadata(a).is_ok_and(|m| {
            let mode = m.permissions().mode();
            if m.is_dir() {
                mode & 0o001 != 0
            } else {
                mode & 0o004 != 0
            }
        })
    })
}

impl Sandbox {
    /// At [`Level::User`], before the tests run: refuses when one of `secrets` (the
    /// instructor's project, the hidden tests) is open to other users, or when the build
    /// directory is not (the tests' user must reach its binaries), and closes the graded copy
    /// (which holds the hidden tests while they run) to other users until [`Sandbox::reopen`].
    /// Nothing at
    /// [`Level::Namespaces`], whose tests see none of these.
    pub fn protect(
        &self,
        secrets: &[&Path],
        target_dir: &Path,
        project: &Path,
    ) -> Result<(), ToolError> {
        use std::os::unix::fs::PermissionsExt;
        if self.policy.level != Level::User {
            return Ok(());
        }
        for s in secrets {
            if open_to_others(s) {
                return Err(ToolError::Usage(format!(
                    "--sandbox user: {} is open to other users, and the tests would read it: close it (chmod o-rwx)",
                    s.display()
                )));
            }
        }
        if !open_to_others(target_dir) {
            return Err(ToolError::Usage(format!(
                "--sandbox user: the build directory {} is closed to other users, and the tests run as one: every directory above it must be searchable (o+x)",
                target_dir.display()
            )));
        }
        // what the submission before left running ends before this one's tests start
        self.policy.sweep_all();
        std::fs::set_permissions(project, std::fs::Permissions::from_mode(0o700))
            .map_err(|e| ToolError::io(project, e))
    }

    /// Opens the graded copy again once the hidden tests have left it (the leaderboard's
    /// render reads its scenes and figures as the tests' user).
    pub fn reopen(&self, project: &Path) -> Result<(), ToolError> {
        use std::os::unix::fs::PermissionsExt;
        if self.policy.level != Level::User {
            return Ok(());
        }
        self.policy.sweep_all();
        std::fs::set_permissions(project, std::fs::Permissions::from_mode(0o755))
            .map_err(|e| ToolError::io(project, e))
    }
}
