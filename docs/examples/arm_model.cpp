// SPDX-License-Identifier: MIT
// The built-in arm from C++: the muscle layer's model API (libmu), whose
// headers are C with extern "C" guards, so a C++ program includes them as
// they are. The handles are held by std::unique_ptr with the layer's
// destroy functions, so they are freed on every path out.
//
// The arm (shoulder, elbow, five muscles) hangs with 1 kg in the hand for
// 2 s, then both biceps contract fully for 1.5 s. The program exits 0 when
// the elbow flexes by more than 30°; it prints the library's version and
// the elbow angle before and after.
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "mu/mu.h"

namespace
{

// Throws the layer's message when a call fails.
void check(rb_status status)
{
    if (status != RB_OK) {
        throw std::runtime_error(rb_last_error());
    }
}

struct description_deleter {
    void operator()(mu_model_desc *desc) const { mu_model_desc_destroy(desc); }
};
struct model_deleter {
    void operator()(mu_model *model) const { mu_model_destroy(model); }
};

// The index of the hinge named `name`.
int hinge_index(const mu_model *model, const std::string &name)
{
    for (int i = 0; i < mu_model_hinge_count(model); ++i) {
        if (name == mu_model_hinge_name(model, i)) {
            return i;
        }
    }
    throw std::runtime_error("no hinge named " + name);
}

// Steps the model for `seconds` of simulated time.
void run(mu_model *model, double seconds)
{
    const double end = mu_model_time(model) + seconds;
    while (mu_model_time(model) < end - 1e-9) {
        check(mu_model_step(model));
    }
}

} // namespace

int main()
{
    try {
        std::printf("arm_model: sinew %s (headers %s)\n", mu_version(), MU_VERSION_STRING);
        mu_model_desc *raw_desc = nullptr;
        check(mu_model_desc_load_builtin("arm", &raw_desc));
        std::unique_ptr<mu_model_desc, description_deleter> desc(raw_desc);

        mu_model_options options = mu_default_model_options();
        options.weight_index = 1; // the weight's second choice: 1 kg
        mu_model *raw_model = nullptr;
        check(mu_model_create(desc.get(), &options, &raw_model));
        std::unique_ptr<mu_model, model_deleter> model(raw_model);

        const int elbow = hinge_index(model.get(), "Elbow");
        run(model.get(), 2.0);
        const double hanging = mu_model_hinge_angle(model.get(), elbow);
        check(mu_model_set_activation(model.get(), "Biceps Short + Biceps Long", 1.0));
        run(model.get(), 1.5);
        const double flexed = mu_model_hinge_angle(model.get(), elbow);

        std::printf("arm_model: elbow %.1f° hanging, %.1f° after 1.5 s of both biceps\n", hanging, flexed);
        return flexed - hanging > 30.0 ? EXIT_SUCCESS : EXIT_FAILURE;
    } catch (const std::exception &error) {
        std::fprintf(stderr, "arm_model: %s\n", error.what());
        return EXIT_FAILURE;
    }
}
