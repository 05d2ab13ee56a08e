#pragma once
// The inspector's tuning (the Tuning panel): `depthscope tune msaa` or `tune alpha` on the
// current view, run off the UI thread with the renderer held (as Diagnose is); its last result
// of each kind kept for the panel's tables, plots and Apply buttons.
#include <chrono>
#include <functional>
#include <future>
#include <optional>
#include <string>

#include "capture/tune/tune_alpha.h"
#include "capture/tune/tune_msaa.h"

namespace ds::ui {

enum class TuneKind : uint8_t { Msaa, Alpha };

// The Tuning panel's Run buttons (Inspector::apply starts it).
struct Tune {
    TuneKind kind = TuneKind::Msaa;
    tune::CostKind cost = tune::CostKind::Fragments;
};

struct TuneResult {
    std::optional<tune::MsaaTune> msaa;
    std::optional<tune::AlphaTune> alpha;
};

class Tuning {
  public:
    ~Tuning() { wait(); }
    void wait();  // for a run in flight (it holds the renderer)
    // Runs `work` on its own thread; ignored while a run is in flight.
    void start(TuneKind kind, std::function<TuneResult()> work);
    // The result, once it landed (call each UI frame): true when one just did.
    bool collect();
    bool running() const { return future_.valid(); }
    TuneKind kind() const { return kind_; }
    double seconds() const;
    const std::optional<tune::MsaaTune>& msaa() const { return msaa_; }
    const std::optional<tune::AlphaTune>& alpha() const { return alpha_; }
    const std::string& error() const { return error_; }

  private:
    std::future<TuneResult> future_;
    TuneKind kind_ = TuneKind::Msaa;
    std::chrono::steady_clock::time_point started_{};
    std::optional<tune::MsaaTune> msaa_;
    std::optional<tune::AlphaTune> alpha_;
    std::string error_;
};

}  // namespace ds::ui
