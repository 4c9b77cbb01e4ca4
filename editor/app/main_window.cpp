// MainWindow: layout, menus, toolbar, docks, title and closing.
#include "main_window.hpp"
#include "cost_panel.hpp"
#include "preferences.hpp"
#include "timeline_bar.hpp"
#include "tree_panel.hpp"
#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoView>
#include <QVBoxLayout>

namespace spt::editor {

MainWindow::MainWindow(const StartOptions& options, QWidget* parent)
    : QMainWindow(parent), start_(options), scene_(doc_), recovery_(options.recovery_dir) {
    setObjectName("spt_editor");
    setAcceptDrops(true);
    // The views over the timeline, which takes no room while the mesh has no clips.
    auto* centre = new QWidget(this);
    auto* column = new QVBoxLayout(centre);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    grid_ = new ViewGrid(doc_, scene_, options_, centre);
    timeline_ = new TimelineBar(doc_, centre);
    column->addWidget(grid_, 1);
    column->addWidget(timeline_);
    setCentralWidget(centre);
    for (int i = 0; i < 4; ++i) {
        connect(grid_->view(i), &ViewWidget::message, this, &MainWindow::show_message);
        connect(grid_->view(i), &ViewWidget::hovered, this, [this](ViewWidget* v) { hover_view_ = v; });
    }
    connect(&doc_, &EditorDocument::poseRefused, this, [this](const QString& why) { show_message("not posed: " + why); });
    build_docks();
    build_menus();

    // A busy bar and its Cancel button in the status bar, hidden until work runs.
    auto add_busy = [this](QProgressBar*& bar, QPushButton*& cancel, const QString& text) {
        bar = new QProgressBar;
        bar->setRange(0, 0);
        bar->setMaximumWidth(160);
        bar->hide();
        cancel = new QPushButton(text);
        cancel->hide();
        statusBar()->addPermanentWidget(bar);
        statusBar()->addPermanentWidget(cancel);
    };
    add_busy(progress_, cancel_, "Cancel");
    cancel_->setObjectName("cancel_open");
    add_busy(build_progress_, build_cancel_, "Cancel build");
    build_cancel_->setObjectName("cancel_build");
    add_busy(motion_progress_, motion_cancel_, "Cancel motion");
    motion_cancel_->setObjectName("cancel_motion");
    motion_progress_->setObjectName("motion_progress");
    connect(motion_cancel_, &QPushButton::clicked, &motion_, &MotionSession::cancel);
    connect(&motion_, &MotionSession::progress, this, [this](int done, int total) {
        motion_progress_->setRange(0, total);
        motion_progress_->setValue(done);
    });
    connect(&motion_, &MotionSession::loaded, this, &MainWindow::motion_loaded);
    connect(&motion_, &MotionSession::failed, this, [this](const QString& why, bool cancelled) {
        update_title();
        motion_progress_->hide();
        motion_cancel_->hide();
        // The document stays, and so does the motion loaded before.
        if (cancelled) show_message(why);
        else show_error(why);
    });
    connect(&motion_, &MotionSession::cleared, this, [this] {
        scene_.set_motion(nullptr);
        cost_->set_motion(nullptr, {});
        update_motion_actions();
    });
    connect(cost_, &CostPanel::finished, this, [this] {
        // The tree box says which motion each tree was last measured on.
        const CostReport* r = cost_->report();
        if (!r || r->motion_label.isEmpty() || r->tree.isEmpty()) return;
        measured_[r->tree] = r->motion_label;
        panel_->set_measured(measured_);
    });
    for (auto signal : {&EditorDocument::treeChanged, &EditorDocument::currentChanged, &EditorDocument::documentReset})
        connect(&doc_, signal, this, &MainWindow::update_motion_actions);
    start_motion_pending_ = !start_.scene.isEmpty();
    // Core's builder stops at its next node of 1,024 samples or more; a result that still
    // arrives is dropped.
    connect(build_cancel_, &QPushButton::clicked, this, [this] {
        if (build_cancel_flag_) *build_cancel_flag_ = true;
        build_progress_->hide();
        build_cancel_->hide();
    });
    connect(&build_watcher_, &QFutureWatcher<BuildJob>::finished, this, &MainWindow::build_finished);
    connect(cancel_, &QPushButton::clicked, this, [this] {
        // Core stops the conversion at its next check; a result that still arrives is dropped.
        if (open_cancel_) *open_cancel_ = true;
        cancelled_ = true;
        progress_->hide();
        cancel_->hide();
        show_message("opening cancelled");
        update_title();
    });
    connect(&watcher_, &QFutureWatcher<LoadResult>::finished, this, [this] {
        progress_->hide();
        cancel_->hide();
        const LoadResult& r = watcher_.result();
        if (!cancelled_) loaded(r);
        else if (r.cancelled)
            show_message(QString("%1: opening cancelled, the %2 stopped").arg(r.path, r.stopped_importing ? "import" : "conversion"));
        opening_ = false;
        update_title();
    });

    save_path_ = start_.output;
    connect(&stack_, &QUndoStack::cleanChanged, this, &MainWindow::update_title);
    connect(&stack_, &QUndoStack::indexChanged, this, &MainWindow::update_title);
    connect(&autosave_timer_, &QTimer::timeout, this, &MainWindow::autosave);
    // The command line's --autosave holds for this session; the rest comes from the preferences.
    Preferences prefs = load_preferences();
    if (start_.autosave_seconds >= 0) prefs.autosave_seconds = start_.autosave_seconds;
    apply_preferences(prefs, false);
    resize(1280, 860);
    update_title();
    if (!start_.file.isEmpty()) open_file(start_.file, start_.mesh);
}

MainWindow::~MainWindow() {
    // Work still running stops at its next check instead of finishing for nobody.
    if (open_cancel_) *open_cancel_ = true;
    if (build_cancel_flag_) *build_cancel_flag_ = true;
    motion_.cancel();
    watcher_.waitForFinished();
    build_watcher_.waitForFinished();
    recovery_.clear();
    // The stack's last signals and the widgets that refer to members go before the members.
    stack_.disconnect(this);
    qDeleteAll(findChildren<QDockWidget*>(Qt::FindDirectChildrenOnly));
    delete takeCentralWidget();
}

void MainWindow::build_docks() {
    panel_ = new TreePanel(doc_, this);
    panel_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Expanding); // grows with the window, as the history
    auto* tree_dock = new QDockWidget("Tree", this);
    tree_dock->setObjectName("tree_dock");
    tree_dock->setWidget(panel_);
    addDockWidget(Qt::RightDockWidgetArea, tree_dock);
    auto* history = history_ = new QUndoView(&stack_);
    history->setEmptyLabel("No document"); // the bottom row: the document as opened, once there is one
    auto* history_dock = new QDockWidget("History", this);
    history_dock->setObjectName("history_dock");
    history_dock->setWidget(history);
    addDockWidget(Qt::RightDockWidgetArea, history_dock);
    cost_ = new CostPanel(doc_, this);
    auto* cost_dock = new QDockWidget("Cost", this);
    cost_dock->setObjectName("cost_dock");
    // Scrolled when short: unscrolled, the panel's chart and table set the tab group's least
    // height and squeezed the tree above it to a few rows.
    auto* cost_scroll = new QScrollArea;
    cost_scroll->setWidget(cost_);
    cost_scroll->setWidgetResizable(true);
    cost_scroll->setFrameShape(QFrame::NoFrame);
    cost_dock->setWidget(cost_scroll);
    addDockWidget(Qt::RightDockWidgetArea, cost_dock);
    tabifyDockWidget(history_dock, cost_dock);
    history_dock->raise();
    connect(cost_, &CostPanel::message, this, &MainWindow::show_message);
    connect(panel_, &TreePanel::setRadiusRequested, this, &MainWindow::set_radius);
    connect(panel_, &TreePanel::buildSubtreeRequested, this, &MainWindow::build_subtree);
    connect(panel_, &TreePanel::colorByChosen, this, [this](render::ColorBy by) { scene_.set_color_by(by); });
}

void MainWindow::build_menus() {
    QMenu* file = menuBar()->addMenu("&File");
    file->addAction("&Open...", QKeySequence::Open, this, [this] {
        const QString p = QFileDialog::getOpenFileName(this, "Open a mesh or a .spt file", {},
                                                       "Meshes and trees (*.spt *.obj *.ply *.stl *.off *.fbx *.dae "
                                                       "*.3ds *.gltf *.glb);;All files (*)");
        if (!p.isEmpty()) open_file(p);
    });
    recent_menu_ = file->addMenu("Open &Recent");
    refresh_recent();
    file->addAction("Load &motion...", this, &MainWindow::choose_motion)->setObjectName("load_motion");
    file->addAction("&Save", QKeySequence::Save, this, [this] { save(); });
    file->addAction("Save &As...", QKeySequence::SaveAs, this, [this] { save_as(); });
    file->addAction("Re&vert", this, [this] { revert(); });
    file->addSeparator();
    file->addAction("&Quit", QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu("&Edit");
    QAction* undo = stack_.createUndoAction(this, "&Undo");
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = stack_.createRedoAction(this, "&Redo");
    // Ctrl+Shift+Z and the platform's redo keys, each once: on X11 the platform's list holds
    // Ctrl+Shift+Z itself, and a sequence given twice is an ambiguous shortcut Qt never fires.
    QList<QKeySequence> redo_keys{QKeySequence("Ctrl+Shift+Z")};
    for (const QKeySequence& k : QKeySequence::keyBindings(QKeySequence::Redo))
        if (!redo_keys.contains(k)) redo_keys.push_back(k);
    redo->setShortcuts(redo_keys);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    QAction* split_action = edit->addAction("&Split by selection", QKeySequence(Qt::Key_S), this, [this] { split(); });
    QAction* merge_action = edit->addAction("&Merge children", QKeySequence(Qt::Key_M), this, [this] { merge(); });
    QAction* build_action = edit->addAction("&Build subtree", QKeySequence(Qt::Key_B), this, [this] { build_subtree(); });
    QAction* motion_action = build_motion_action_ =
        edit->addAction("Build from m&otion", QKeySequence("Shift+B"), this, [this] { build_from_motion(); });
    motion_action->setObjectName("build_from_motion");
    motion_action->setToolTip("Build under the current node for the loaded motion (File > Load motion), Shift+B");
    motion_action->setEnabled(false);
    edit->addSeparator();
    edit->addAction("Add tree", this, [this] { add_tree(); });
    edit->addAction("Rename tree...", this, [this] {
        if (!doc_.has_tree()) return;
        bool ok = false;
        const QString name = QInputDialog::getText(this, "Rename tree", "Name", QLineEdit::Normal,
                                                   QString::fromStdString(doc_.tree().name()), &ok);
        if (ok) rename_tree(name);
    });
    edit->addAction("Duplicate tree", this, [this] { duplicate_tree(); });
    edit->addAction("Delete tree", this, [this] { delete_tree(); });
    edit->addSeparator();
    edit->addAction("&Preferences...", QKeySequence("Ctrl+,"), this, &MainWindow::show_preferences);

    build_select_menu();

    QMenu* view = menuBar()->addMenu("&View");
    QAction* visible = visible_action_ = view->addAction("&Visible-only selection");
    visible->setCheckable(true);
    visible->setShortcut(QKeySequence(Qt::Key_X));
    connect(visible, &QAction::toggled, this, [this](bool on) {
        options_.visible_only = on;
        show_message(on ? "selection: visible only" : "selection: through");
    });
    QAction* swap = swap_action_ = view->addAction("Shift/Ctrl as in MeshLab (Ctrl adds)");
    swap->setCheckable(true);
    connect(swap, &QAction::toggled, this, [this](bool on) { options_.swap_modifiers = on; });
    view->addAction("Frame &all", QKeySequence(Qt::Key_Home), this, [this] {
        for (int i = 0; i < 4; ++i) grid_->view(i)->frame_all();
    });
    view->addAction("&Frame selection", QKeySequence(Qt::Key_F), this, [this] {
        for (int i = 0; i < 4; ++i) grid_->view(i)->frame_selection();
    });
    view->addAction("&Maximise view", QKeySequence("Ctrl+Space"), this, [this] {
        ViewWidget* v = grid_->view_at(QCursor::pos());
        if (!v) v = qobject_cast<ViewWidget*>(focusWidget());
        grid_->toggle_maximised(v);
    });
    view->addSeparator();
    view->addAction("&Hide node", QKeySequence(Qt::Key_H), this, &MainWindow::hide_current);
    view->addAction("&Isolate node", QKeySequence("Shift+H"), this, &MainWindow::isolate_current);
    view->addAction("&Show all nodes", QKeySequence("Alt+H"), this, &MainWindow::show_all_nodes);

    QToolBar* tools = addToolBar("Edit");
    tools->setObjectName("edit_toolbar");
    tools->addAction(split_action);
    tools->addAction(merge_action);
    tools->addAction(build_action);
    tools->addAction(motion_action);
    tools->addAction(visible);
    tools->addSeparator();
    for (QAction* a : tool_group_->actions()) tools->addAction(a);
}

void MainWindow::build_select_menu() {
    QMenu* select = menuBar()->addMenu("Se&lect");
    tool_group_ = new QActionGroup(this);
    auto add_tool = [&](const QString& text, const QKeySequence& key, SelectTool tool, const char* name) {
        QAction* a = select->addAction(text, key, this, [this, tool] { set_select_tool(tool); });
        a->setCheckable(true);
        a->setChecked(tool == options_.tool);
        a->setObjectName(name);
        tool_group_->addAction(a);
    };
    add_tool("&Rectangle", QKeySequence(Qt::Key_R), SelectTool::Rectangle, "tool_rectangle");
    add_tool("&Lasso", QKeySequence(Qt::Key_L), SelectTool::Lasso, "tool_lasso");
    add_tool("&Circle brush", QKeySequence(Qt::Key_C), SelectTool::Brush, "tool_brush");
    select->addAction("Brush smaller", QKeySequence(Qt::Key_BracketLeft), this,
                      [this] { set_brush_radius(options_.brush_radius / 1.25); });
    select->addAction("Brush larger", QKeySequence(Qt::Key_BracketRight), this,
                      [this] { set_brush_radius(options_.brush_radius * 1.25); });
    select->addSeparator();
    select->addAction("Select li&nked under the cursor", QKeySequence("Ctrl+L"), this,
                      [this] { select_linked(SelectionMode::Add); });
    select->addAction("Deselect linked under the cursor", QKeySequence("Ctrl+Shift+L"), this,
                      [this] { select_linked(SelectionMode::Subtract); });
    select->addAction("&Invert", QKeySequence("Ctrl+I"), this, &MainWindow::invert_selection);
    QAction* grow = select->addAction("&Grow", this, &MainWindow::grow_selection);
    grow->setShortcuts({QKeySequence(QKeyCombination(Qt::ControlModifier | Qt::KeypadModifier, Qt::Key_Plus)), QKeySequence("Ctrl++")});
    QAction* shrink = select->addAction("S&hrink", this, &MainWindow::shrink_selection);
    shrink->setShortcuts({QKeySequence(QKeyCombination(Qt::ControlModifier | Qt::KeypadModifier, Qt::Key_Minus)), QKeySequence("Ctrl+-")});
}

void MainWindow::set_select_tool(SelectTool tool) {
    options_.tool = tool;
    const char* names[] = {"tool_rectangle", "tool_lasso", "tool_brush"};
    for (QAction* a : tool_group_->actions()) a->setChecked(a->objectName() == names[int(tool)]);
    show_message(tool == SelectTool::Rectangle ? "select: rectangle"
                 : tool == SelectTool::Lasso   ? "select: lasso"
                                               : QString("select: circle brush, radius %1 pixels").arg(options_.brush_radius, 0, 'f', 1));
}

void MainWindow::set_brush_radius(double radius) {
    options_.brush_radius = std::clamp(radius, 2.0, 500.0);
    show_message(QString("brush radius %1 pixels").arg(options_.brush_radius, 0, 'f', 1));
}

void MainWindow::select_linked(SelectionMode mode) {
    ViewWidget* v = hover_view_ ? hover_view_ : qobject_cast<ViewWidget*>(focusWidget());
    if (!v) return show_message("select linked: point at a view first");
    v->select_linked(mode);
}

void MainWindow::apply_operation(StrokeKind kind, const QString& what) {
    if (!doc_.has_tree()) return show_message("no document is open");
    RecipeStroke op;
    op.kind = kind;
    QString why;
    doc_.apply(op, &why);
    if (!why.isEmpty()) return show_message(what + ": " + why);
    show_message(QString("%1: %2 selected in node %3").arg(what).arg(doc_.selection().size()).arg(qulonglong(doc_.current())));
}

void MainWindow::invert_selection() { apply_operation(StrokeKind::Invert, "invert"); }
void MainWindow::grow_selection() { apply_operation(StrokeKind::Grow, "grow"); }
void MainWindow::shrink_selection() { apply_operation(StrokeKind::Shrink, "shrink"); }

void MainWindow::hide_current() {
    doc_.hide(doc_.current());
    show_message(QString("node %1 hidden (Alt+H shows all)").arg(qulonglong(doc_.current())));
}

void MainWindow::isolate_current() {
    doc_.isolate(doc_.current());
    show_message(QString("only node %1 shown (Alt+H shows all)").arg(qulonglong(doc_.current())));
}

void MainWindow::show_all_nodes() {
    doc_.show_all();
    show_message("every node shown");
}

bool MainWindow::modified() const { return unsaved_new_ || !stack_.isClean(); }

void MainWindow::update_title() {
    QString name = !save_path_.isEmpty() ? save_path_ : source_path_;
    name = name.isEmpty() ? QString("untitled") : QFileInfo(name).fileName();
    // Scripts wait for the title without "(opening)" to know the document is in.
    // ... and without " (loading motion)" to know the motion of --scene is in.
    setWindowTitle(QString("%1[*] - spt-editor%2")
                       .arg(name, loading() ? " (opening)" : motion_.loading() ? " (loading motion)" : ""));
    setWindowModified(modified());
}

void MainWindow::show_error(const QString& text) {
    last_error_ = text;
    statusBar()->showMessage(text);
    // Window-modal and not blocking: the document and the views stay as they were.
    auto* box = new QMessageBox(QMessageBox::Warning, "spt-editor", text, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::show_message(const QString& text) {
    last_message_ = text;
    statusBar()->showMessage(text);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (maybe_save()) {
        recovery_.clear();
        timeline_->pause(); // the document closes: no clip plays on for a hidden window
        event->accept();
    } else {
        event->ignore();
    }
}

bool MainWindow::maybe_save() {
    if (!modified()) return true;
    const auto answer = QMessageBox::question(this, "spt-editor", "The document has unsaved changes. Save them?",
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.front().isLocalFile()) open_file(urls.front().toLocalFile());
}

} // namespace spt::editor
