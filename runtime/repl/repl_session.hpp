// The REPL's state and what each input does to it, without a terminal (runtime/repl/repl.cpp reads the
// lines).
//
// The session is a script: the statements accepted so far, in order. An input is accepted only when the
// whole session, with it, evaluates without error — so an error never changes the state. A definition
// of a name the session already has replaces the old one (the newest wins; the old statement is dropped
// and named in the reply). An expression alone is evaluated after the session and its value shown
// (a solid as faces, edges and bounds). Input the parser could not finish (it stopped at the end:
// an open brace, a trailing operator) waits for more lines. `:` commands look at and save the scene;
// see help_text().
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera_adjust.hpp"
#include "core/device/page/hidden_style.hpp"
#include "runtime/base/file_access.hpp"
#include "runtime/base/limits.hpp"
#include "runtime/repl/terminal_graphics.hpp"
#include "runtime/repl/terminal_picture.hpp"

namespace hlr::runtime {

struct ReplReply {
  enum class Kind { Done, More, Error, Quit } kind = Kind::Done;
  std::string text;  // to print (ends in '\n' when not empty)
};

class ReplSession {
 public:
  explicit ReplSession(TerminalSize size = {});

  // One line of input (without its newline). Ctrl-C (interrupt_requested()) stops its work; the
  // session then stays as it was.
  ReplReply feed(const std::string& line);
  // Drops a half-typed statement (Ctrl-C at the prompt).
  void cancel_input() { pending_.clear(); }
  bool continuing() const { return !pending_.empty(); }

  // The session as a runnable script (what :save writes).
  std::string script() const;
  // Words for Tab: keywords, built-ins, the session's names, commands.
  std::vector<std::string> completions(const std::string& line, const std::string& word) const;

  void set_terminal_size(TerminalSize size) { size_ = size; }
  // The folders the session's scripts may read beyond their own, and where their outputs go (--allow-path,
  // --out-dir); the limits of each evaluation (--limit, --frame-timeout).
  void set_run_options(AccessOptions access, const Limits& limits) {
    access_ = std::move(access);
    limits_ = limits;
  }
  // How :show draws: braille text, or the real picture of `pixels` for kitty and sixel terminals.
  void set_graphics(TerminalGraphics kind, PixelSize pixels) {
    graphics_ = kind;
    pixels_ = pixels;
  }

 private:
  struct Chunk {
    std::string text;                // one accepted input, as typed
    std::vector<std::string> names;  // the top-level names it defines
    std::vector<std::string> cameras;
  };
  struct View;  // a rendered frame

  ReplReply feed_line(const std::string& line);
  ReplReply accept(const std::string& text);
  ReplReply evaluate_expression(const std::string& text);
  ReplReply command(const std::string& line);
  ReplReply help(const std::string& topic) const;
  // The parameters of the function the session's name or a built-in names (for completion).
  std::vector<std::string> parameter_names(const std::string& function) const;
  ReplReply load(const std::filesystem::path& path);
  ReplReply show();
  ReplReply stats();
  ReplReply scene();
  ReplReply frames();
  ReplReply render(const std::string& file);
  ReplReply save(const std::string& file);
  ReplReply step_camera(const std::string& command, const std::string& arguments);
  std::string join(const std::vector<Chunk>& chunks) const;
  // The session as drawn: its statements, and the stepped camera (:orbit, :zoom, :dolly) when there is
  // one, declared last as adjust(<the camera's expression>, ...).
  std::string view_text(const std::vector<Chunk>& chunks) const;
  std::optional<std::string> drawn_camera() const;  // the name to draw with, when not the last declared
  std::optional<View> view(std::string& error) const;

  // Everything an input or a command may change, as :undo puts it back.
  struct State {
    std::vector<Chunk> chunks;
    int frame = 0;
    std::optional<HiddenStyle> hidden;
    std::optional<std::string> camera;
    std::optional<CameraAdjustment> step;
    std::string stepped_name;
    std::optional<std::filesystem::path> loaded;
  };
  State state() const { return {chunks_, frame_, hidden_, camera_, step_, stepped_name_, loaded_}; }
  void restore(State s);
  // After a change succeeded: `before` is what one :undo of `what` (":orbit 30", "a statement") restores.
  void remember(std::string what, State before) { undo_.push_back({std::move(what), std::move(before)}); }

  TerminalSize size_;
  TerminalGraphics graphics_ = TerminalGraphics::Braille;
  PixelSize pixels_{0, 0};
  std::vector<Chunk> chunks_;
  std::vector<std::pair<std::string, State>> undo_;  // what each change did, and the state before it
  std::string pending_;                              // lines of an unfinished statement
  int frame_ = 0;
  std::optional<HiddenStyle> hidden_;            // :hidden on|off, :levels N
  std::optional<std::string> camera_;            // :camera NAME
  std::optional<CameraAdjustment> step_;         // :orbit, :zoom, :dolly since the camera was chosen
  std::string stepped_name_;                     // the adjusted camera's name in view_text()
  std::optional<std::filesystem::path> loaded_;  // for :reload
  AccessOptions access_;
  Limits limits_;
};

// The commands and what they do, one line each.
std::string repl_help_text();

}  // namespace hlr::runtime
