//! A readable listing of compiled code (`edgewise disasm`), for students who
//! want to see the "assembly" the papers' system ran.

use super::compiler::{Algorithm, MessageItem, Op};
use super::types::Type;
use std::fmt::Write as _;

/// Lists an algorithm's registers and instructions, one instruction a line,
/// each with its source line and the source text it executes.
pub fn disassemble(algorithm: &Algorithm) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "algorithm {}", algorithm.signature());
    if let Some(description) = &algorithm.description {
        let _ = writeln!(out, "  description: {description}");
    }
    let variables: Vec<String> = algorithm
        .variables
        .iter()
        .map(|v| {
            format!(
                "{} : {}{}",
                v.name,
                v.ty,
                if v.is_param { " (parameter)" } else { "" }
            )
        })
        .collect();
    let _ = writeln!(
        out,
        "  variables: {}",
        if variables.is_empty() {
            "none".to_owned()
        } else {
            variables.join(", ")
        }
    );
    let temporaries =
        algorithm.registers.len() - algorithm.variables.len().min(algorithm.registers.len());
    let _ = writeln!(
        out,
        "  registers: {} ({} for intermediate values and constants)",
        algorithm.registers.len(),
        temporaries
    );
    let width = algorithm.code.len().saturating_sub(1).to_string().len();
    for (pc, instr) in algorithm.code.iter().enumerate() {
        let text = instruction_text(algorithm, instr.op);
        let source = algorithm.snippet(instr.span);
        let _ = writeln!(
            out,
            "  {pc:>width$}  line {:<4} {text:<34} ; {source}",
            instr.line
        );
    }
    out
}

/// The disassembly of every algorithm, separated by blank lines.
pub fn disassemble_all<'a>(algorithms: impl IntoIterator<Item = &'a Algorithm>) -> String {
    algorithms
        .into_iter()
        .map(disassemble)
        .collect::<Vec<_>>()
        .join("\n")
}

fn instruction_text(algorithm: &Algorithm, op: Op) -> String {
    let name = |reg| algorithm.register_name(reg);
    match op {
        Op::Lookup { dst, base, field } => {
            let field = field.lookup_name();
            format!("lookup   {} := {}.{field}", name(dst), name(base))
        }
        Op::Assign { var, src } => format!("assign   {} := {}", name(var), name(src)),
        Op::Write { base, field, src } => {
            let field = field.lookup_name();
            format!("write    {}.{field} := {}", name(base), name(src))
        }
        Op::New { dst, kind } => format!("new      {} := {}", name(dst), Type::of_kind(kind)),
        Op::Delete { element } => format!("delete   {}", name(element)),
        Op::Call {
            dst,
            builtin,
            args,
            argc,
        } => {
            let args: Vec<String> = args
                .iter()
                .take(usize::from(argc))
                .map(|&reg| name(reg))
                .collect();
            format!(
                "call     {} := {}({})",
                name(dst),
                builtin.name(),
                args.join(", ")
            )
        }
        Op::Compare {
            dst,
            op,
            left,
            right,
        } => {
            format!(
                "compare  {} := {} {} {}",
                name(dst),
                name(left),
                op.symbol(),
                name(right)
            )
        }
        Op::Compute {
            dst,
            op,
            left,
            right,
        } => {
            if op.is_unary() {
                format!("compute  {} := {} {}", name(dst), op.symbol(), name(left))
            } else {
                format!(
                    "compute  {} := {} {} {}",
                    name(dst),
                    name(left),
                    op.symbol(),
                    name(right)
                )
            }
        }
        Op::Invoke { dst, routine, args } => {
            let callee = algorithm.routines().get(usize::from(routine));
            let count = callee.map_or(0, super::compiler::Routine::param_count);
            let args: Vec<String> = algorithm
                .call_arguments(args, count)
                .iter()
                .map(|&reg| name(reg))
                .collect();
            let callee = callee.map_or("?", |c| c.name.as_str());
            let call = format!("{callee}({})", args.join(", "));
            if algorithm.register_type(dst) == Type::Null {
                format!("call     {call}")
            } else {
                format!("call     {} := {call}", name(dst))
            }
        }
        Op::Return { src, value: true } => format!("return   {}", name(src)),
        Op::Return { value: false, .. } => "return".to_owned(),
        Op::Index { dst, array, index } => {
            format!("index    {} := {}[{}]", name(dst), name(array), name(index))
        }
        Op::Store { array, index, src } => {
            format!("store    {}[{}] := {}", name(array), name(index), name(src))
        }
        Op::Append { array, src } => format!("append   {}, {}", name(array), name(src)),
        Op::Length { dst, array } => format!("length   {} := {}", name(dst), name(array)),
        Op::Move { dst, src } => format!("move     {} := {}", name(dst), name(src)),
        Op::Mark { element } => format!("mark     {}", name(element)),
        Op::Highlight { element } => format!("highlight {}", name(element)),
        Op::Refuse { index } => format!("refuse   message {index}"),
        Op::Message { index } => {
            let items: Vec<String> = algorithm
                .messages
                .get(index as usize)
                .map(|t| {
                    t.items
                        .iter()
                        .map(|item| match item {
                            MessageItem::Text(text) => format!("\"{text}\""),
                            MessageItem::Value(reg) => name(*reg),
                        })
                        .collect()
                })
                .unwrap_or_default();
            format!("message  {}", items.join(", "))
        }
        Op::Jump { target } => format!("jump     {target}"),
        Op::JumpIf {
            cond,
            when: true,
            target,
        } => format!("jumpif   {} -> {target}", name(cond)),
        Op::JumpIf {
            cond,
            when: false,
            target,
        } => format!("jumpif   not {} -> {target}", name(cond)),
        Op::Done => "done".to_owned(),
    }
}
