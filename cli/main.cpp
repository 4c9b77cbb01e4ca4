// spt: command-line front end. Messages go to stderr; results to stdout or files.
// Exit codes: 0 ok, 1 usage, 2 bad input, 3 cannot write (docs/cli.md).
#include "exit_code.hpp"
#include "commands.hpp"
#include "spt/error.hpp"
#include "spt/version.hpp"
#include <iostream>
#include <map>

int main(int argc, char** argv) {
    CLI::App app{"spt: collision detection with sampling trees"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "spt " SPT_VERSION_STRING);
    std::map<CLI::App*, spt::cli::Action> actions;
    auto add = [&](spt::cli::Action (*make)(CLI::App&)) {
        const size_t before = app.get_subcommands({}).size();
        spt::cli::Action a = make(app);
        actions[app.get_subcommands({})[before]] = std::move(a);
    };
    add(spt::cli::add_convert_command);
    add(spt::cli::add_info_command);
    add(spt::cli::add_query_command);
    add(spt::cli::add_simulate_command);
#ifdef SPT_HAVE_RENDER
    add(spt::cli::add_render_command);
#else
    add(spt::cli::add_render_left_out);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "spt: " << e.what() << "\n(run 'spt --help' or 'spt COMMAND --help')\n";
        return 1;
    }
    try {
        for (auto& [sub, action] : actions)
            if (sub->parsed()) return action();
    } catch (const spt::Error& e) {
        std::cerr << "spt: error: " << e.what() << "\n";
        return spt::cli::exit_code(e.kind());
    } catch (const std::bad_alloc&) {
        std::cerr << "spt: error: out of memory\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "spt: error: " << e.what() << "\n";
        return 2;
    }
    return 1;
}
