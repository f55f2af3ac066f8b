# bash completion for hlrscript. Options come from `hlrscript --help` itself, so they never drift; plotter
# profiles from `hlrscript --list-plotters`; camera names from `hlrscript --list-cameras FILE` (the script
# already on the line, evaluated as `check` does).
#   installed: share/bash-completion/completions/hlrscript; by hand: source completions/hlrscript.bash

_hlrscript_script() {  # the .hls file already on the command line
  local w
  for w in "${COMP_WORDS[@]:1}"; do
    [[ $w == *.hls && -f $w ]] && { printf '%s\n' "$w"; return; }
  done
}

_hlrscript() {
  local cur prev program=${COMP_WORDS[0]}
  cur=${COMP_WORDS[COMP_CWORD]}
  prev=${COMP_WORDS[COMP_CWORD-1]}
  COMPREPLY=()
  case $prev in
    -o|--output)
      # Every device's extension; a {frame:03} pattern is typed by hand.
      local files ext
      files=$(compgen -f -- "$cur")
      COMPREPLY=($(compgen -d -S / -- "$cur"))
      for ext in pdf svg png hpgl plt gcode nc steps json jsonl dxf off obj stl; do
        COMPREPLY+=($(compgen -f -X "!*.$ext" -- "$cur"))
      done
      [[ -n $cur && $cur != *.* ]] && for ext in pdf svg png hpgl gcode json jsonl; do COMPREPLY+=("$cur.$ext"); done
      compopt -o nospace 2>/dev/null
      return ;;
    --camera)
      local script
      script=$(_hlrscript_script)
      [[ -n $script ]] && COMPREPLY=($(compgen -W "$("$program" --list-cameras "$script" 2>/dev/null)" -- "$cur"))
      return ;;
    --plotter)
      COMPREPLY=($(compgen -W "$("$program" --list-plotters 2>/dev/null)" -- "$cur")); return ;;
    --hidden) COMPREPLY=($(compgen -W "off dashed" -- "$cur")); return ;;
    --svg) COMPREPLY=($(compgen -W "plotter document" -- "$cur")); return ;;
    --fit) COMPREPLY=($(compgen -W "camera drawing" -- "$cur")); return ;;
    --text) COMPREPLY=($(compgen -W "stroke outline" -- "$cur")); return ;;
    --hpgl-moves) COMPREPLY=($(compgen -W "relative absolute" -- "$cur")); return ;;
    --pen-order) COMPREPLY=($(compgen -W "none greedy optimized" -- "$cur")); return ;;
    --json) COMPREPLY=($(compgen -W "all camera layout segments strokes stats strokes,stats" -- "$cur")); return ;;
    --paper) COMPREPLY=($(compgen -W "A0 A1 A2 A3 A4 A5 A6 Letter Legal Tabloid" -- "$cur")); return ;;
    --limit) COMPREPLY=($(compgen -W "steps= faces= vertices= segments= memory= calls= list= string=" -- "$cur"))
      compopt -o nospace 2>/dev/null; return ;;
    --allow-path|--out-dir) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    --levels) COMPREPLY=($(compgen -W "1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16" -- "$cur")); return ;;
    --frames|--shard|--jobs|-j|--margin|--scale|--dash|--dpi|--line-width|--step|--plan-effort|--frame-timeout)
      return ;;  # a number or a range: nothing to offer
  esac
  if [[ $cur == -* ]]; then
    local options
    options=$("$program" --help 2>/dev/null | grep -E '^ +-' | grep -oE -- '--[a-z][a-z-]*' | sort -u)
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
    return
  fi
  # The first word: a command or a script; after it, scripts.
  if ((COMP_CWORD == 1)); then
    COMPREPLY=($(compgen -W "check watch repl help" -- "$cur"))
  fi
  COMPREPLY+=($(compgen -d -S / -- "$cur") $(compgen -f -X '!*.hls' -- "$cur"))
  [[ ${#COMPREPLY[@]} -eq 1 && ${COMPREPLY[0]} == */ ]] && compopt -o nospace 2>/dev/null
}
complete -F _hlrscript hlrscript
