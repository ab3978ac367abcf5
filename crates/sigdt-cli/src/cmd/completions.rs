//! `sigdt completions SHELL`: a completion script for bash, zsh, fish, elvish or PowerShell,
//! and the hidden `sigdt manpages --out DIR`: roff man pages of `sigdt` and each subcommand
//! (`make man`). Both are generated from the clap definitions, so they never drift from the
//! arguments the program takes.

use std::io::Write;
use std::path::PathBuf;

use anyhow::{Context, Result};
use clap::Args;
use clap_complete::Shell;

use crate::messages::note;

/// `sigdt completions`.
#[derive(Debug, Args)]
#[command(after_help = "\
Install, for example:
  bash: sigdt completions bash > ~/.local/share/bash-completion/completions/sigdt
  zsh:  sigdt completions zsh > ~/.zfunc/_sigdt   (with fpath+=~/.zfunc before compinit)
  fish: sigdt completions fish > ~/.config/fish/completions/sigdt.fish")]
pub struct CompletionsArgs {
    /// The shell.
    #[arg(value_enum, value_name = "SHELL")]
    pub shell: Shell,
}

/// `sigdt manpages` (hidden).
#[derive(Debug, Args)]
pub struct ManpagesArgs {
    /// Folder for sigdt.1 and sigdt-SUBCOMMAND.1.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

/// `sigdt completions`: the script of the command line `cli` on standard output.
pub fn completions(args: &CompletionsArgs, mut cli: clap::Command) -> Result<()> {
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut cli, "sigdt", &mut script);
    let mut out = std::io::stdout().lock();
    match out.write_all(&script).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(e).context("<stdout>"),
        _ => Ok(()),
    }
}

/// `sigdt manpages`: one page per command of the command line `cli`, the subcommands' pages
/// named `sigdt-NAME.1`.
pub fn manpages(args: &ManpagesArgs, cli: clap::Command) -> Result<()> {
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("{}: cannot create the folder", args.out.display()))?;
    let mut pages = vec![("sigdt.1".to_string(), cli.clone())];
    for sub in cli.get_subcommands().filter(|s| !s.is_hide_set()) {
        let name = format!("sigdt-{}", sub.get_name());
        let usage = format!("sigdt {}", sub.get_name());
        pages.push((format!("{name}.1"), sub.clone().name(name).bin_name(usage)));
    }
    for (file, command) in pages {
        let mut page = Vec::new();
        clap_mangen::Man::new(command).render(&mut page)?;
        let path = args.out.join(&file);
        crate::output::write_file(&path, &page)?;
    }
    note(&format!("wrote the man pages to {}", args.out.display()));
    Ok(())
}
